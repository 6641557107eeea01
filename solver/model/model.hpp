// Model: the validated, immutable description of a deck that the analysis runs.
// Built only by inp::read_deck; everything is in internal (0-based, dense) indices,
// with the deck's labels kept for output.
#pragma once

#include <array>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "core/error.hpp"
#include "core/types.hpp"
#include "element/element_type.hpp"
#include "material/hardening_curves.hpp"
#include "material/deformation_plasticity.hpp"
#include "material/hyperelastic_potential.hpp"
#include "material/temperature_table.hpp"
#include "model/contact.hpp"
#include "model/local_frame.hpp"
#include "model/solution_controls.hpp"
#include "model/tie.hpp"

namespace kontakt::model {

/// What a 2D element of the deck stands for. ccx (and Kontakt) solve such elements as one layer
/// of 3D elements with out-of-plane constraints (model/plane_expansion).
enum class Planar { None, PlaneStress, PlaneStrain, Axisymmetric };

struct Element {
  int id = 0;                     ///< label in the deck
  element::ElementType type{};    ///< for a 2D element: the 3D type it is expanded into
  std::vector<int> nodes;         ///< internal node indices, ccx local order
  int section = -1;               ///< index into Model::sections
  Planar planar = Planar::None;   ///< CPS*, CPE*, CAX* as read (kept after the expansion)
};

/// A node of 2D elements after the expansion: its U is the weighted mean of the expanded
/// nodes' displacements and its RF their sum, as ccx reports them.
struct PlanarFold {
  int node = 0;                   ///< internal index of the deck's 2D node
  std::vector<int> expanded;      ///< internal indices of all its expanded nodes
  std::vector<Real> weights;      ///< parallel to expanded, summing to 1
};

struct Mesh {
  std::vector<int> node_ids;      ///< deck label of each internal node
  MatX3 coords;                   ///< one row per internal node
  std::unordered_map<int, int> node_index;     ///< label -> internal index
  std::vector<Element> elements;
  std::unordered_map<int, int> element_index;  ///< label -> internal index
};

/// A GENERATE data line: first, first + step, ... up to last. Kept as a range, not expanded,
/// because a range may name far more labels than the mesh has (ccx keeps them so too).
struct LabelRange {
  int first = 0;
  int last = 0;
  int step = 1;
  long long count() const { return (static_cast<long long>(last) - first) / step + 1; }
  bool contains(int label) const {
    return label >= first && label <= last && (static_cast<long long>(label) - first) % step == 0;
  }
};

/// Members are stored sorted by deck label and free of duplicates. ccx 2.20 prints a set as it
/// was defined instead: its labels and GENERATE ranges in deck order, a set named in a set
/// standing for its entries at that card, duplicates kept (and summed twice in TOTALS=),
/// labels without a node or element up to the largest label printed as zero rows (nodes) or
/// skipped (elements). `print_order` keeps that sequence, a label as a range of one; sets
/// Kontakt builds itself leave it empty and print their members.
struct NodeSet {
  std::string name;               ///< upper case, as ccx prints it
  std::vector<int> nodes;         ///< internal indices
  std::vector<LabelRange> print_order{};
};
struct ElementSet {
  std::string name;
  std::vector<int> elements;      ///< internal indices
  std::vector<LabelRange> print_order{};
};

struct ElementFace {
  int element = 0;                ///< internal element index
  int face = 0;                   ///< 1-based ccx face number
};
struct Surface {
  enum class Kind { ElementFaces, Nodes };
  std::string name;
  Kind kind = Kind::ElementFaces;
  std::vector<ElementFace> faces;  ///< Kind::ElementFaces
  std::vector<int> nodes;          ///< Kind::Nodes, internal indices
  SourceLoc where;
};

struct Material {
  std::string name;
  /// *ELASTIC, isotropic: (E, nu) per temperature (one row: constant); empty: not given
  material::TemperatureTable<2> elastic;
  /// *ELASTIC, TYPE=ORTHO / ENGINEERING CONSTANTS / ANISO: the 21 D_IJKL of ccx's ANISO order
  /// (material/anisotropic_elastic) per temperature, in the material frame; empty: isotropic.
  material::TemperatureTable<21> anisotropic;
  /// *HYPERELASTIC (polynomial family, OGDEN) or *HYPERFOAM, one temperature: instead of
  /// *ELASTIC; NLGEOM only.
  std::optional<material::HyperelasticPotential> hyperelastic;
  /// *DEFORMATION PLASTICITY (one temperature): instead of *ELASTIC; NLGEOM only.
  std::optional<material::RambergOsgood> deformation_plasticity;
  material::TemperatureTable<1> density;    ///< *DENSITY per temperature
  material::TemperatureTable<1> expansion;  ///< *EXPANSION, isotropic secant coefficient
  Real expansion_zero = 0;                  ///< *EXPANSION, ZERO= reference temperature
  /// *PLASTIC: one curve per temperature; empty for an elastic material. Its HARDENING= rule,
  /// and for COMBINED the *CYCLIC HARDENING curves (the yield surface's size).
  material::HardeningCurves plastic;
  material::HardeningRule hardening_rule = material::HardeningRule::Isotropic;
  material::HardeningCurves cyclic;
  SourceLoc where;

  bool has_elastic() const {
    return !elastic.empty() || !anisotropic.empty() || hyperelastic.has_value() ||
           deformation_plasticity.has_value();
  }
};

struct SolidSection {
  std::string elset;
  int material = -1;              ///< index into Model::materials
  SourceLoc where;
  Real thickness = 1;             ///< data line of plane stress / strain elements (ccx default 1)
  Real offset = 0;                ///< OFFSET=: their mid-plane at z = -offset * thickness
  /// ORIENTATION=: the material frame, in which an anisotropic material's constants are given
  /// and *EL PRINT without GLOBAL=YES prints S and E (ccx); none: the global axes.
  std::optional<Orientation> orientation;
};

struct Amplitude {
  std::string name;
  bool total_time = false;        ///< TIME=TOTAL TIME; otherwise step time
  std::vector<std::pair<Real, Real>> points;  ///< (time, value), time ascending
  /// Piecewise-linear value; constant beyond the table ends.
  Real value_at(Real time) const;
};

/// *TIME POINTS: times at which nonlinear steps end an increment and write their output.
struct TimePoints {
  std::string name;
  bool total_time = false;        ///< TIME=TOTAL TIME; otherwise step time
  std::vector<Real> times;        ///< ascending, no repeats
};

/// One term of a linear multipoint constraint sum(coef * u[node][dof]) = 0.
struct EquationTerm {
  int node = 0;                   ///< internal index
  int dof = 0;                    ///< 0, 1, 2 = x, y, z
  Real coef = 0;
};
struct Equation {
  std::vector<EquationTerm> terms;  ///< the first term's dof is the dependent one (ccx)
  SourceLoc where;
  std::string keyword = "*EQUATION";  ///< the card it comes from (*EQUATION, *TIE), for messages
};

/// A two-node element outside the solid library, assembled as a node pair
/// (analysis/connector): a SPRINGA spring (*SPRING), a GAPUNI gap (*GAP) or a T3D2 truss
/// (*SOLID SECTION with the cross-sectional area).
/// A truss is a connector, not a solid element family: it is the spring's axial member with
/// another force law, and node pairs already assemble, count as support and print here.
struct Connector {
  enum class Kind { Spring, Gap, Truss };
  Kind kind = Kind::Spring;
  int id = 0;                     ///< deck label
  std::array<int, 2> nodes{};     ///< internal indices
  /// Spring: the force against the elongation (final minus initial length): linear with
  /// `stiffness`, or piecewise linear through `curve` (elongation, force), ascending, constant
  /// beyond its ends (ccx).
  Real stiffness = 0;
  std::vector<std::pair<Real, Real>> curve;
  /// Gap: open while clearance + direction . (u_2 - u_1) >= 0; closed, a penalty of
  /// `stiffness` with the tensile force `tension` at infinite opening (ccx's node-to-face
  /// linear law).
  Real clearance = 0;
  Vec3 direction = Vec3::UnitX();
  Real tension = 0;
  /// Truss: an isotropic elastic bar of cross-section `area` (a St. Venant-Kirchhoff bar under
  /// NLGEOM, as ccx's expanded element behaves; analysis/truss).
  Real area = 0;
  Real young = 0, poisson = 0;
  SourceLoc where;                ///< its *ELEMENT line
};

/// The deck's name of a connector kind: SPRINGA, GAPUNI, T3D2.
std::string_view connector_type_name(Connector::Kind kind);

/// A nonlinear multiple point constraint g(u) = 0 over the dofs of a few nodes, solved for
/// one dependent dof (*RIGID BODY, *MPC PLANE / STRAIGHT / MEANROT / DIST;
/// assembly/nonlinear_constraint).
struct NonlinearConstraint {
  enum class Kind {
    Rigid,     ///< nodes {p, ref, rot}: x_p = x_ref + R(u_rot) (X_p - X_ref) in `component`
    Plane,     ///< nodes {p, a, b, c}: p stays in the plane through a, b and c
    Straight,  ///< nodes {p, a, b}: p stays on the line through a and b (two constraints)
    /// nodes {n_1 .. n_N, e}: the mean rotation of n_1 .. n_N about the axis through their
    /// centre along e's coordinates is e's first dof (ccx's MEANROT, manual section 8.7.1)
    MeanRotation,
    /// nodes {a, b}: |x_a - x_b| = `distance`, in force only while the two are linked: the
    /// distance may not exceed it (ccx's DIST; analysis/distance_links decides when)
    Distance,
  };
  Kind kind = Kind::Rigid;
  std::vector<int> nodes;  ///< internal indices, in the roles of `kind`
  int component = 0;       ///< the dependent dof: this component of nodes[0]
  int pivot = 0;           ///< Straight: the component of the line's direction g is scaled by
  Real distance = 0;       ///< Distance: the largest distance
  SourceLoc where;
  std::string keyword;     ///< *RIGID BODY or *MPC, for messages
};

/// *PRE-TENSION SECTION, SURFACE=: a bolt cut along an element-face surface, opened or loaded
/// through the first dof of a reference node (model/pretension).
struct PretensionSection {
  std::string surface;            ///< upper-case name of an element-face surface
  int node = 0;                   ///< internal index of the reference node
  Vec3 normal = Vec3::UnitX();    ///< unit, pointing away from the elements owning the faces
  SourceLoc where;
};

/// A prescribed displacement u[node][dof] = value * amplitude(t). Fixed = value 0.
struct Boundary {
  int node = 0;
  int dof = 0;
  Real value = 0;
  int amplitude = -1;             ///< index into Model::amplitudes, -1 = ramp/step default
  /// *BOUNDARY, FIXED: hold the displacement reached at the end of the previous step
  /// (zero in the first step); `value` is unused.
  bool hold_previous = false;
};
struct ConcentratedLoad {
  int node = 0;
  int dof = 0;
  Real value = 0;
  int amplitude = -1;
};
/// Uniform pressure on an element face (*DLOAD Pn); positive pushes into the face.
struct PressureLoad {
  ElementFace face;
  Real value = 0;
  int amplitude = -1;
};

/// *DLOAD GRAV or CENTRIF on a set of elements: an acceleration field acting on their mass.
struct BodyLoad {
  enum class Kind { Gravity, Centrifugal };
  Kind kind = Kind::Gravity;
  std::vector<int> elements;      ///< internal indices
  Real value = 0;                 ///< GRAV: the acceleration; CENTRIF: omega^2
  Vec3 point = Vec3::Zero();      ///< CENTRIF: a point on the axis
  Vec3 direction = Vec3::UnitZ(); ///< unit: GRAV the acceleration's direction, CENTRIF the axis
  int amplitude = -1;
  SourceLoc where;
};

enum class Totals { No, Yes, Only };

/// *NODE PRINT / *EL PRINT request (printed to .dat).
struct PrintRequest {
  enum class Kind { Node, Element };
  Kind kind = Kind::Node;
  std::string set;                ///< NSET= / ELSET= name (upper case)
  std::vector<std::string> variables;  ///< upper case: U, RF, S, E, EVOL, ENER, ...
  Totals totals = Totals::No;
  bool global = false;            ///< GLOBAL= (ccx default NO: transformed nodes print local)
  int frequency = 1;
  SourceLoc where;
};

/// *NODE FILE / *EL FILE / *NODE OUTPUT / *ELEMENT OUTPUT: fields written to the results file.
struct FileRequest {
  std::vector<std::string> variables;
  int frequency = 1;
};

struct StaticProcedure {
  Real initial_increment = 1;
  Real period = 1;
  std::optional<Real> min_increment;
  std::optional<Real> max_increment;
  bool direct = false;
  bool data_line_given = false;
};

/// One *STEP. Loads and constraints are the *effective* set for the step: the reader has
/// already applied carry-over from earlier steps, OP=NEW and model-level definitions.
struct Step {
  SourceLoc where;
  bool nlgeom = false;
  int max_increments = 100;       ///< *STEP, INC=
  StaticProcedure procedure;
  /// TIME POINTS= of an output request in force (index into Model::time_points): output only
  /// at these times and at the step end, FREQUENCY= set aside (ccx); -1: none.
  int time_points = -1;
  model::SolutionControls controls;  ///< *CONTROLS in force for this step
  std::vector<Boundary> boundaries;
  std::vector<ConcentratedLoad> cloads;
  std::vector<PressureLoad> pressures;
  std::vector<BodyLoad> body_loads;
  /// Nodal temperatures at the end of the step (*TEMPERATURE), size n_nodes, or empty when
  /// the step has no temperature field (then the initial temperatures apply).
  VecX temperatures;
  std::vector<PrintRequest> prints;
  std::vector<FileRequest> node_files, element_files;
  ContactControls contact_controls;  ///< *CONTROLS, PARAMETERS=CONTACT / LINE SEARCH in force
  std::vector<ContactRequest> contact_prints, contact_files;
  /// Per interaction (Model::interactions order): the friction in force in this step, i.e. the
  /// interaction's *FRICTION as changed by *CHANGE FRICTION in this or an earlier step.
  std::vector<std::optional<Friction>> interaction_friction;
  /// *CHANGE SOLID SECTION in this or an earlier step: the section (Model::sections index) of
  /// every element in this step; empty: each element's own Element::section.
  std::vector<int> element_sections;
  /// Per *CONTACT PAIR of the deck (Model::contact_pairs order): 0 where *MODEL CHANGE, TYPE=
  /// CONTACT PAIR, REMOVE took it out in this or an earlier step (and no ADD brought it back).
  /// Pairs beyond the vector (TIED pairs of *TIE) are active.
  std::vector<char> contact_pair_active;
  /// Per element: 0 where *MODEL CHANGE, TYPE=ELEMENT, REMOVE took it out in this or an earlier
  /// step (and no ADD brought it back); empty: every element is active. An element added back
  /// is strain-free in the configuration of the step it returns in (ccx).
  std::vector<char> element_active;
  /// Per interaction: the *SURFACE BEHAVIOR in force in this step (the interaction's own, as
  /// changed by *CHANGE SURFACE BEHAVIOR in this or an earlier step).
  std::vector<SurfaceBehavior> interaction_behavior;
};

struct Model {
  std::string heading;
  std::string source_file;        ///< the deck that was read
  Mesh mesh;
  std::map<std::string, NodeSet> node_sets;       ///< key: upper-case name
  std::map<std::string, ElementSet> element_sets;
  std::map<std::string, Surface> surfaces;
  std::vector<Material> materials;
  std::vector<SolidSection> sections;
  std::vector<Amplitude> amplitudes;
  std::vector<TimePoints> time_points;
  std::vector<Equation> equations;
  /// Re-linearised at every iteration of an NLGEOM step, linear (at the undeformed state)
  /// otherwise.
  std::vector<NonlinearConstraint> nonlinear_constraints;
  std::vector<Connector> connectors;
  /// Local nodal systems of *TRANSFORM (the last one naming a node wins, as in ccx): internal
  /// node -> its local axes as columns (model::local_frame). *BOUNDARY, *CLOAD and *EQUATION
  /// dofs of these nodes are local components.
  std::unordered_map<int, Mat3> local_frames;
  std::vector<SurfaceInteraction> interactions;
  std::vector<ContactPair> contact_pairs;  ///< all pairs of the deck (model level, as in ccx)
  /// *TIE, deck order; contact::apply_ties turns them into `equations` before the analysis.
  std::vector<Tie> ties;
  /// *PRE-TENSION SECTION, deck order; model::split_pretension_sections cuts the mesh along
  /// them and adds their `equations` after the 2D expansion.
  std::vector<PretensionSection> pretension_sections;
  /// *CYCLIC SYMMETRY MODEL, deck order; contact::apply_ties turns each with its tie into
  /// `equations`.
  std::vector<CyclicSymmetry> cyclic_symmetry;
  /// Initial nodal temperatures (*INITIAL CONDITIONS, TYPE=TEMPERATURE), size n_nodes, or
  /// empty when none were given.
  VecX initial_temperatures;
  /// Initial stresses (*INITIAL CONDITIONS, TYPE=STRESS) per element: n_ip x 6 (xx yy zz xy xz
  /// yz, ccx point order), empty for an element without; the vector is empty when none.
  std::vector<MatX> initial_stresses;
  std::vector<Step> steps;
  /// One entry per deck node of 2D elements (model::expand_planar_elements); empty otherwise.
  std::vector<PlanarFold> planar_folds;
  std::vector<std::string> warnings;  ///< "file:line: keyword: message" for accepted oddities

  int n_nodes() const { return static_cast<int>(mesh.node_ids.size()); }
  int n_elements() const { return static_cast<int>(mesh.elements.size()); }
};

}  // namespace kontakt::model
