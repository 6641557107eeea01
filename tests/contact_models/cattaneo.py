"""Cattaneo-Mindlin partial slip (friction.md §5.2) of line contact: the full-width Hertz model
of hertz.py (cylinder R = 1 on a block, identical materials E = 1000, nu = 0.3, so the normal and
tangential problems uncouple; plane strain, one element layer with u_z = 0) with Coulomb friction
mu = 0.3 and stick slope lambda = 1e6 (lambda b / G = 260 >= 100: the stick compliance does not
blur the stick zone), K = 1.1e6 as in hertz.py.

Step 1: the cylinder's axis plane moved down by DELTA = 0.02 (held in x): the normal load P
(b ~ 0.109). Step 2: the axis plane moved in x by DRAG in INCREMENTS equal increments at the same
approach (identical materials: P stays constant); the tangential load Q (a reaction) rises to
~0.85 mu P. Output: *NODE PRINT RF of the axis plane (P, Q), *CONTACT FILE (the contact point
table with positions and stick/slip status per increment, HDF5).

Closed form (Johnson ch. 7): stick zone |x - x_0| < c with c / b = sqrt(1 - Q / (mu P)), q = mu p
in the slip zones c < |x - x_0| < b.

Point contact (`cattaneo_sphere`): the half model of hertz_sphere.py (symmetry plane y = 0,
parallel to the load; sphere R = 1 on a block, the same materials, K, mu, lambda), the cap's
top moved down by 0.012 (a ~ 0.1) in 6 increments, then in x by SPHERE_DRAG at that approach.
Stick circle c / a = (1 - Q / (mu P))^(1/3).
"""
import hertz
import hertz_sphere

MU, STICK_SLOPE = 0.3, 1e6
DRAG, INCREMENTS = 1.1e-2, 10
SPHERE_DRAG, SPHERE_INCREMENTS = 3.2e-3, 8


def cattaneo(level=2, contact_type="SURFACE TO SURFACE", drag=DRAG, increments=INCREMENTS):
    model = hertz.hertz("C3D8", level, contact_type, full_width=True)
    model.heading = "Kontakt contact model: Cattaneo-Mindlin line contact (partial slip)"
    model.friction = (MU, STICK_SLOPE)
    fraction = 1.0 / increments
    model.later_steps = [((fraction, 1.0, 1e-5, fraction), [("UPPER", "YMAX", 1, 1, drag)])]
    model.notes.append(f"Cattaneo-Mindlin (friction.md 5.2): mu {MU:g}, lambda {STICK_SLOPE:g}, "
                       f"tangential drag {drag:g} of the axis plane in {increments} increments")
    return model


def cattaneo_sphere(ratio=10, drag=SPHERE_DRAG, increments=SPHERE_INCREMENTS):
    model = hertz_sphere.hertz_sphere("C3D8", ratio, half=True)
    model.heading = "Kontakt contact model: Cattaneo-Mindlin point contact (partial slip)"
    model.friction = (MU, STICK_SLOPE)
    fraction = 1.0 / increments
    model.later_steps = [((fraction, 1.0, 1e-5, fraction), [("UPPER", "ZMAX", 1, 1, drag)])]
    model.notes.append(f"Cattaneo-Mindlin (friction.md 5.2), half model: mu {MU:g}, lambda "
                       f"{STICK_SLOPE:g}, tangential drag {drag:g} of the cap's top in "
                       f"{increments} increments")
    return model
