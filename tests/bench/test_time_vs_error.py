"""Unit tests of the pure parts of time_vs_error.py: Pareto fronts and the dominance verdict
(pareto.py), the headline error, the CSV completeness check and the smoke's convergence check.
Run: /usr/bin/python3 -m unittest test_time_vs_error   (in this folder)"""
import os
import sys
import tempfile
import unittest

import numpy as np

sys.dont_write_bytecode = True  # keep the source tree clean

import pareto  # noqa: E402
import time_vs_error  # noqa: E402  (puts tests/contact_models on the path)
import solvers  # noqa: E402


class Front(unittest.TestCase):
    def test_dominated_runs_leave_the_front(self):
        runs = [(1.0, 0.5), (2.0, 0.1), (3.0, 0.2), (1.5, 0.6), (4.0, 0.05)]
        self.assertEqual(pareto.pareto_front(runs), [(1.0, 0.5), (2.0, 0.1), (4.0, 0.05)])

    def test_equal_time_keeps_the_lower_error_only(self):
        self.assertEqual(pareto.pareto_front([(1.0, 0.3), (1.0, 0.2)]), [(1.0, 0.2)])
        self.assertEqual(pareto.pareto_front([(2.0, 0.2), (1.0, 0.2)]), [(1.0, 0.2)])

    def test_identical_runs_both_stay(self):
        self.assertEqual(pareto.pareto_front([(1.0, 0.2), (1.0, 0.2), (3.0, 0.3)]),
                         [(1.0, 0.2), (1.0, 0.2)])

    def test_runs_without_error_never_enter_nor_beat(self):
        # a fast run that did not converge must not remove the slower converged one
        self.assertEqual(pareto.pareto_front([(0.1, None), (5.0, 0.4)]), [(5.0, 0.4)])
        self.assertEqual(pareto.pareto_front([(0.1, None)]), [])

    def test_sorted_by_time(self):
        self.assertEqual(pareto.pareto_front([(3.0, 0.01), (1.0, 1.0), (2.0, 0.1)]),
                         [(1.0, 1.0), (2.0, 0.1), (3.0, 0.01)])


class Dominance(unittest.TestCase):
    def test_every_run_matched(self):
        v = pareto.dominance([(1.0, 0.1), (3.0, 0.01)], [(2.0, 0.1), (3.0, 0.02)])
        self.assertTrue(v.dominates)
        self.assertEqual(v.matched, [((2.0, 0.1), (1.0, 0.1)), ((3.0, 0.02), (3.0, 0.01))])

    def test_one_run_faster_at_its_error_is_not_dominated(self):
        v = pareto.dominance([(1.0, 0.1), (3.0, 0.01)], [(2.0, 0.05), (5.0, 0.1)])
        self.assertFalse(v.dominates)
        self.assertEqual(v.unmatched, [(2.0, 0.05)])
        self.assertIn("1 of 2", v.reason)

    def test_more_accurate_run_is_not_dominated(self):
        v = pareto.dominance([(1.0, 0.1)], [(10.0, 0.001)])
        self.assertFalse(v.dominates)

    def test_equal_run_is_matched(self):
        self.assertTrue(pareto.dominance([(1.0, 0.1)], [(1.0, 0.1)]).dominates)

    def test_error_tolerance(self):
        # within 1 % the errors are equal: the faster run matches; beyond it, it does not
        self.assertFalse(pareto.dominance([(1.0, 0.01005)], [(2.0, 0.01)]).dominates)
        self.assertTrue(pareto.dominance([(1.0, 0.01005)], [(2.0, 0.01)], 0.01).dominates)
        self.assertFalse(pareto.dominance([(1.0, 0.0102)], [(2.0, 0.01)], 0.01).dominates)

    def test_empty_fronts(self):
        self.assertTrue(pareto.dominance([(1.0, 0.1)], []).dominates)
        self.assertFalse(pareto.dominance([], [(1.0, 0.1)]).dominates)
        self.assertFalse(pareto.dominance([], []).dominates)


def row(problem="patch", solver="kontakt", scheme="lgc7", setting="random000",
        status="converged", error="0.01"):
    r = {c: "" for c in time_vs_error.COLUMNS}
    r.update(problem=problem, solver=solver, scheme=scheme, setting=setting, status=status,
             wall_s="1.0", error=error)
    return r


class Checks(unittest.TestCase):
    def test_headline_is_the_largest_magnitude(self):
        self.assertEqual(time_vs_error.headline(
            "hertz_line", {"error_p0": 0.02, "error_p0_fit": -0.05, "error_radius": 0.01}), 0.05)
        self.assertIsNone(time_vs_error.headline(
            "patch", {"error_szz": 0.0, "error_cpress": float("inf")}))

    def test_point_raises_errors_below_the_resolution(self):
        self.assertEqual(time_vs_error.point(row(error="0")), (1.0, time_vs_error.ERROR_FLOOR))
        self.assertEqual(time_vs_error.point(row(error="")), (1.0, None))

    def test_complete_csv(self):
        rows = [row(), row(solver="ccx", scheme="node-to-surface")]
        keys = [("patch", "kontakt", "lgc7", "random000"),
                ("patch", "ccx", "node-to-surface", "random000")]
        self.assertEqual(time_vs_error.completeness(time_vs_error.COLUMNS, rows, keys), [])

    def test_missing_column(self):
        header = [c for c in time_vs_error.COLUMNS if c != "iterations"]
        self.assertEqual(time_vs_error.completeness(header, [], []), ["column iterations missing"])

    def test_missing_repeated_and_unexpected_rows(self):
        keys = [("patch", "kontakt", "lgc7", "random000"), ("patch", "kontakt", "nts", "random000")]
        found = time_vs_error.completeness(
            time_vs_error.COLUMNS, [row(), row(), row(setting="random007")], keys)
        self.assertEqual(sorted(found), sorted([
            "no row for ('patch', 'kontakt', 'nts', 'random000')",
            "2 rows for ('patch', 'kontakt', 'lgc7', 'random000')",
            "unexpected row ('patch', 'kontakt', 'lgc7', 'random007')"]))

    def test_smoke_flags_kontakt_runs_without_error(self):
        rows = [row(), row(scheme="nts", status="not converged", error=""),
                row(scheme="gc7", status="not measured", error=""),
                row(solver="ccx", scheme="node-to-surface", status="not converged", error="")]
        failures = time_vs_error.smoke_failures(rows)
        self.assertEqual(len(failures), 2)
        self.assertTrue(failures[0].startswith("patch random000 kontakt nts: not converged"))


class Plot(unittest.TestCase):
    def test_the_time_axis_holds_every_run_from_seconds_to_minutes(self):
        rows = [dict(row(problem="hertz_sphere", error="0.33"), wall_s="2.16"),
                dict(row(problem="hertz_sphere", scheme="nts", error="0.055"), wall_s="513.7"),
                dict(row(problem="hertz_sphere", solver="ccx", scheme="surface-to-surface",
                         error="0.026"), wall_s="814.1")]
        with tempfile.TemporaryDirectory() as d:
            left, right = time_vs_error.plot("hertz_sphere", rows, os.path.join(d, "p.png"))
        self.assertTrue(0 < left < 2.16 and right > 814.1, (left, right))


class Repeats(unittest.TestCase):
    @staticmethod
    def solves(*runs):
        """solve_once() handing out the given (converged, wall, cpu) runs in turn, and the list
        of those handed out."""
        handed = []

        def solve_once():
            converged, wall, cpu = runs[len(handed)]
            handed.append(solvers.Run(converged, "converged" if converged else "not converged",
                                      3, 1, wall, 10.0, "dir", "", cpu))
            return handed[-1]
        return solve_once, handed

    def test_a_short_run_keeps_its_least_times(self):
        solve_once, handed = self.solves((True, 0.05, 0.04), (True, 0.02, 0.03), (True, 0.09, 0.01))
        run = time_vs_error.least_wall_time(solve_once)
        self.assertEqual(len(handed), time_vs_error.REPEATS)
        self.assertEqual((run.wall, run.cpu), (0.02, 0.01))

    def test_a_long_or_failed_run_is_solved_once(self):
        for first in ((True, time_vs_error.SHORT_RUN_S, 1.0), (False, 0.01, 0.01)):
            solve_once, handed = self.solves(first, (True, 0.001, 0.001))
            run = time_vs_error.least_wall_time(solve_once)
            self.assertEqual((len(handed), run.wall), (1, first[1]))


class SphereCases(unittest.TestCase):
    def test_each_element_type_at_each_ratio(self):
        size = dict(time_vs_error.SMOKE, patch=0, ratios=[4, 6], quadratic_ratios=[3],
                    sphere_elements=["C3D8", "C3D20"],
                    line_elements=[], penalties=[], increments=[], slides=[], blocks=[],
                    hueeber_levels=[])
        study = time_vs_error.cases(size, seed=1)
        self.assertEqual([c.setting for c in study],
                         ["C3D8 a/h 4", "C3D8 a/h 6", "C3D20 a/h 3"])
        types = [{e.etype for e in [c.model.upper.mesh]} for c in study]
        self.assertEqual(types, [{"C3D8"}, {"C3D8"}, {"C3D20"}])

    def test_the_full_study_meshes_both_element_types_at_the_same_node_spacing(self):
        self.assertEqual([2 * r for r in time_vs_error.FULL["quadratic_ratios"]],
                         time_vs_error.FULL["ratios"])

    def test_the_full_study_has_both_element_types(self):
        self.assertEqual(time_vs_error.FULL["sphere_elements"], ["C3D8", "C3D20"])


class BlockProblems(unittest.TestCase):
    def test_fixed_points_lie_inside_one_element_of_every_mesh(self):
        for n in (4, 8, 16):
            for x, y, z in time_vs_error.block_measure.fixed_points(time_vs_error.BLOCK_CENTRE):
                for c in (x, y, z):
                    self.assertGreater(abs(c * n - round(c * n)), 1e-6, (n, c))

    def test_element_at_finds_the_element_holding_the_point(self):
        mesh = time_vs_error.block_model("cube", 4).lower.mesh
        eid = time_vs_error.block_measure.element_at(mesh, np.array([0.6, 0.1, 0.9]))
        xyz = np.array([mesh.nodes[n] for n in mesh.elements[eid]])
        np.testing.assert_allclose(xyz.min(axis=0), [0.5, 0.0, 0.75])
        with self.assertRaises(ValueError):
            time_vs_error.block_measure.element_at(mesh, np.array([0.5, 0.5, 1.5]))

    def test_von_mises(self):
        vm = time_vs_error.block_measure.von_mises
        self.assertAlmostEqual(vm((0, 0, -7, 0, 0, 0)), 7)
        self.assertAlmostEqual(vm((0, 0, 0, 0, 2, 0)), 2 * 3 ** 0.5)
        self.assertAlmostEqual(vm((5, 5, 5, 0, 0, 0)), 0)

    def test_errors_against_the_reference(self):
        ref = {"settlement": -2.0, "von_mises": [10.0, 20.0, 40.0]}
        run = {"settlement": -2.5, "von_mises": [12.0, 20.0, 34.0]}
        e = time_vs_error.block_measure.errors(run, ref)
        self.assertAlmostEqual(e["error_u"], 0.25)
        self.assertAlmostEqual(e["error_vm"], 6.0 / 40.0)

    def test_cases_per_level_and_a_failed_reference_is_no_error(self):
        size = dict(time_vs_error.SMOKE, patch=0, ratios=[], line_elements=[], penalties=[],
                    increments=[], slides=[], blocks=["punch", "cube"], block_levels=[4, 8],
                    hueeber_levels=[])

        def failed(problem):
            raise ValueError(f"the reference run of the {problem} did not converge")
        study = time_vs_error.cases(size, seed=1, reference=failed)
        self.assertEqual([(c.problem, c.setting) for c in study],
                         [("punch", "C3D8 4^3"), ("punch", "C3D8 8^3"),
                          ("cube", "C3D8 4^3"), ("cube", "C3D8 8^3")])
        self.assertEqual(len(study[1].model.lower.mesh.elements), 8 ** 3)
        with self.assertRaises(ValueError):
            study[0].measure(None)


class HueeberBlocks(unittest.TestCase):
    blocks = time_vs_error.hueeber_blocks
    measure = time_vs_error.hueeber_measure

    def setUp(self):
        self.model = self.blocks.hueeber(2)

    def test_side_loads_sum_to_the_traction_resultants(self):
        # per side: 1e5 inwards and 1e6 downwards over 0.01 x 0.001: 1 N and 10 N
        mesh, offset = self.model.lower.mesh, 0
        by_side = {side: np.zeros(2) for side in ("XMIN", "XMAX")}
        for body, node, dof, force in self.model.cloads:
            self.assertEqual(body, "LOWER")
            side = "XMIN" if node in mesh.nsets["XMIN"] else "XMAX"
            self.assertIn(node - offset, mesh.nsets[side])
            by_side[side][dof - 1] += force
        np.testing.assert_allclose(by_side["XMIN"], [1.0, -10.0], rtol=1e-12)
        np.testing.assert_allclose(by_side["XMAX"], [-1.0, -10.0], rtol=1e-12)

    def test_bodies_touch_without_overlap_on_non_matching_meshes(self):
        lower = np.array(list(self.model.lower.mesh.nodes.values()))
        upper = np.array(list(self.model.upper.mesh.nodes.values()))
        self.assertAlmostEqual(lower[:, 1].max(), self.blocks.SIDE)
        self.assertAlmostEqual(upper[:, 1].min(), self.blocks.SIDE)
        self.assertEqual(len(self.model.lower.mesh.elements), 12 * 12)
        self.assertEqual(len(self.model.upper.mesh.elements), 14 * 14)
        xs_lower = {round(x, 12) for x in lower[:, 0]}
        xs_upper = {round(x, 12) for x in upper[:, 0]}
        # 12 and 14 elements: only the ends and the middle meet
        self.assertEqual(sorted(xs_lower & xs_upper), [0.0, 0.005, 0.01])

    def test_sets_of_the_deck(self):
        # the deck's slave (listed first) is the lower block's top; its upper top moves down
        self.assertEqual(self.model.slave, ("LOWER", "YMAX"))
        self.assertEqual(self.model.master, ("UPPER", "YMIN"))
        self.assertEqual(len(self.model.faces("LOWER", "YMAX")), 12)
        self.assertEqual(len(self.model.faces("UPPER", "YMIN")), 14)
        self.assertIn(("LOWER", "YMIN", 1, 2, 0.0), self.model.fixed)
        self.assertIn(("UPPER", "YMAX", 1, 1, 0.0), self.model.fixed)
        self.assertIn(("UPPER", "YMAX", 2, 2, -5e-7), self.model.fixed)

    def test_deck_scale_is_the_suite_mesh(self):
        model = self.blocks.blocks(self.blocks.DECK_SCALE)
        self.assertEqual(len(model.lower.mesh.elements), 60 * 60)
        self.assertEqual(len(model.upper.mesh.elements), 70 * 70)

    def test_settlement_is_the_area_weighted_mean(self):
        # u_y = -1 - x / SIDE: the mean over the top is -1.5 (the end nodes count half)
        u = {n: (0.0, -1.0 - x[0] / self.blocks.SIDE, 0.0)
             for n, x in self.model.lower.mesh.nodes.items()}
        self.assertAlmostEqual(self.measure.settlement(self.model, u), -1.5)

    def nodal(self, model, pressure):
        # the slave is the lower block's top: node ids without offset
        return {n: (0.0, pressure(x[0])) for n, x in model.lower.mesh.nodes.items()
                if n in model.lower.mesh.nsets["YMAX"]}

    def test_pressure_difference_at_the_reference_nodes(self):
        fine = self.blocks.hueeber(3)
        linear = lambda x: 1e6 * x / self.blocks.SIDE  # noqa: E731
        reference = {"settlement": -2.0,
                     "profile": self.measure.pressure_profile(fine, self.nodal(fine, linear))}
        exact = {"settlement": -2.0,
                 "profile": self.measure.pressure_profile(self.model, self.nodal(self.model,
                                                                                 linear))}
        e = self.measure.errors(exact, reference)
        self.assertEqual(e["error_u"], 0.0)
        self.assertLess(e["error_cpress"], 1e-9)
        shifted = {"settlement": -2.5, "profile": self.measure.pressure_profile(
            self.model, self.nodal(self.model, lambda x: linear(x) + 2e5))}
        e = self.measure.errors(shifted, reference)
        self.assertAlmostEqual(e["error_u"], 0.25)
        self.assertAlmostEqual(e["error_cpress"], 2e5 / 1e6)  # over the reference's peak

    def test_a_reference_that_does_not_press_is_refused(self):
        flat = {"settlement": -2.0, "profile": self.measure.pressure_profile(
            self.model, self.nodal(self.model, lambda x: 0.0))}
        with self.assertRaises(ValueError):
            self.measure.errors(flat, flat)

    def test_cases_per_level_and_a_failed_reference_is_no_error(self):
        size = dict(time_vs_error.SMOKE, patch=0, ratios=[], line_elements=[], penalties=[],
                    increments=[], slides=[], blocks=[], hueeber_levels=[1, 2])

        def failed():
            raise ValueError("the reference run did not converge")
        study = time_vs_error.cases(size, seed=1, hueeber_reference=failed)
        self.assertEqual([(c.problem, c.setting) for c in study],
                         [("hueeber", "level 1 (6/7)"), ("hueeber", "level 2 (12/14)")])
        with self.assertRaises(ValueError):
            study[0].measure(None)

    def test_smoke_expects_the_hueeber_rows(self):
        self.assertEqual(time_vs_error.SMOKE["hueeber_levels"], [1])
        size = dict(time_vs_error.SMOKE, patch=0, ratios=[], line_elements=[], penalties=[],
                    increments=[], slides=[], blocks=[])
        keys = time_vs_error.expected_keys(time_vs_error.cases(size, seed=1),
                                           time_vs_error.SMOKE["schemes"], "kontakt", ccx=True)
        self.assertEqual(len(keys), 5)
        self.assertIn(("hueeber", "ccx", "surface-to-surface", "level 1 (6/7)"), keys)


class PenaltyStudy(unittest.TestCase):
    def test_cases_carry_the_penalty_of_their_setting(self):
        size = dict(time_vs_error.SMOKE, patch=0, ratios=[], line_elements=[], blocks=[],
                    penalties=[1, 1e4], penalty_ratio=4, increments=[], slides=[],
                    hueeber_levels=[])
        study = time_vs_error.cases(size, seed=1)
        self.assertEqual([c.setting for c in study], ["K a/E* 1", "K a/E* 10000"])
        e_star, a = time_vs_error.hertz_sphere.E_STAR, time_vs_error.hertz_sphere.TARGET_RADIUS
        for case, r in zip(study, (1, 1e4)):
            self.assertEqual(case.problem, "hertz_penalty")
            self.assertAlmostEqual(case.model.penalty, r * e_star / a)
        # the mesh is the a/h asked for, not the default sphere's
        default = time_vs_error.hertz_sphere.hertz_sphere(ratio=4)
        self.assertEqual(len(study[0].model.upper.mesh.nodes), len(default.upper.mesh.nodes))
        self.assertNotEqual(study[0].model.penalty, default.penalty)


class IncrementStudy(unittest.TestCase):
    def setUp(self):
        size = dict(time_vs_error.SMOKE, patch=0, ratios=[], line_elements=[], penalties=[], blocks=[],
                    increments=[1, 3], increment_ratio=4, slides=[], hueeber_levels=[])
        self.study = time_vs_error.cases(size, seed=1)

    def test_each_increment_count_with_and_without_the_drift_check(self):
        self.assertEqual([c.setting for c in self.study],
                         ["1 increments", "1 increments, drift check off",
                          "3 increments", "3 increments, drift check off"])
        for case, n in zip(self.study, (1, 1, 3, 3)):
            self.assertEqual(case.model.increment[0], 1.0 / n)  # initial = largest increment
            self.assertEqual(case.model.increment[3], 1.0 / n)
        self.assertEqual(self.study[0].kontakt_args, ())
        self.assertEqual(self.study[1].kontakt_args, ("--drift-check", "off"))

    def test_drift_check_off_runs_only_the_linear_variants(self):
        schemes = ["nts", "gc7", "lgc7", "lgauss"]
        on = time_vs_error.case_columns(self.study[0], schemes, "kontakt", ("NODE TO SURFACE",))
        off = time_vs_error.case_columns(self.study[1], schemes, "kontakt", ("NODE TO SURFACE",))
        self.assertEqual([s for _, s, _ in on], schemes + ["node-to-surface"])
        self.assertEqual(off, [("kontakt", "lgc7", "lgc7"), ("kontakt", "lgauss", "lgauss")])
        # the completeness check expects exactly these rows
        expected = time_vs_error.expected_keys(self.study[:2], schemes, "kontakt", ccx=True)
        self.assertEqual(len(expected), 4 + 2 + 2)  # 4 schemes and 2 ccx types, then 2 linear


class DriftStudy(unittest.TestCase):
    def test_each_slide_count_with_and_without_the_drift_check(self):
        size = dict(time_vs_error.SMOKE, patch=0, ratios=[], line_elements=[], penalties=[],
                    blocks=[], increments=[], slides=[1, 4], hueeber_levels=[])
        study = time_vs_error.cases(size, seed=1)
        self.assertEqual([(c.problem, c.setting) for c in study],
                         [("sliding_increments", "1 increments"),
                          ("sliding_increments", "1 increments, drift check off"),
                          ("sliding_increments", "4 increments"),
                          ("sliding_increments", "4 increments, drift check off")])
        for case, n in zip(study, (1, 1, 4, 4)):
            step = case.model.later_steps[0][0]
            self.assertEqual((step[0], step[3]), (1.0 / n, 1.0 / n))  # the slide's increments
            self.assertEqual(case.model.increment, (1.0, 1.0, 1e-5, 1.0))  # the press: as given
        self.assertEqual(study[1].kontakt_args, ("--drift-check", "off"))
        self.assertTrue(study[1].linear_variants_only)
        self.assertEqual(time_vs_error.STUDIES["sliding_increments"][0](study[3].setting), 4.0)

    def test_smoke_has_no_drift_study(self):
        self.assertEqual(time_vs_error.SMOKE["slides"], [])


if __name__ == "__main__":
    unittest.main()
