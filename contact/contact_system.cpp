#include "contact/contact_system.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <span>
#include <sstream>

#include "contact/contact_extrapolation.hpp"
#include "contact/master_search.hpp"
#include "contact/slave_points.hpp"
#include "contact/state_transfer.hpp"
#include "output/contact_records.hpp"
#include "core/error.hpp"
#include "core/parallel.hpp"

namespace kontakt::contact {

using Kind = model::ContactScheme::Kind;

namespace {

/// Node-to-surface pairing is redone in the first evaluations of an increment and then frozen
/// (ccx: iterations up to 8), so the active set can settle; afterwards points without a contact
/// element are still paired at every evaluation, so one that arrives gets its element (none is
/// deleted). Without that a point open at the last re-pairing while the iterate still swung
/// (a load applied in one increment) passed through the master unheld to the converged state,
/// which then had to be paired again and iterated from far off: line Hertz C3D8 level 3 with
/// nts 90 -> 15 iterations, the thesis punch at 8^3 with nts from failing after 272 to 11.
constexpr int kRepairEvaluations = nonlinear::kRepairingIterations;
constexpr Real kNoClearanceLimit = std::numeric_limits<Real>::infinity();
/// The broad phase looks this many of a slave face's (node's faces') sizes around it.
constexpr Real kCandidateMargin = 2;

/// ccx's nodal weights of a slave face's area for node-to-surface contact: the consistent
/// weights for linear faces, positive substitutes for quadratic ones (negative corner weights
/// make node-to-surface contact diverge).
Real nodal_area_weight(element::Topology topo, int local) {
  switch (topo) {
    case element::Topology::Tri3: return 1.0 / 3;
    case element::Topology::Quad4: return 0.25;
    case element::Topology::Tri6: return local < 3 ? 1.0 / 999 : 332.0 / 999;
    case element::Topology::Quad8: return local < 4 ? 1.0 / 100 : 24.0 / 100;
    default: return 0;
  }
}

}  // namespace

ContactSystem::ContactSystem(const model::Model& model)
    : model_(model), no_displacement_(VecX::Zero(3 * model.mesh.coords.rows())) {
  for (const auto& def : model.contact_pairs) {
    Pair pair;
    pair.def = &def;
    pair.scheme = def.scheme;
    pair.behavior = model.interactions.at(def.interaction).behavior;
    pair.law = make_pressure_law(pair.behavior, pair.scheme.linear);
    pair.penalty = reference_stiffness(pair.law);
    pair.slave = make_contact_surface(model, model.surfaces.at(def.slave));
    pair.master = make_contact_surface(model, model.surfaces.at(def.master));
    if (pair.master.faces.empty())
      throw InputError(def.where, "*CONTACT PAIR",
                       "master surface " + def.master + " has no element faces");
    const bool nts = pair.scheme.kind == Kind::NodeToSurface;
    bool tied = pair.behavior.law == model::SurfaceBehavior::Law::Tied;
    for (const model::Step& step : model.steps)
      tied |= static_cast<std::size_t>(def.interaction) < step.interaction_behavior.size() &&
              step.interaction_behavior[def.interaction].law == model::SurfaceBehavior::Law::Tied;
    if (nts && tied)
      throw InputError(def.where, "*CONTACT PAIR",
                       "PRESSURE-OVERCLOSURE=TIED is face-to-face contact: use TYPE=SURFACE TO "
                       "SURFACE (or a segment scheme) for this pair");
    if (!nts && pair.slave.faces.empty())
      throw InputError(def.where, "*CONTACT PAIR",
                       "scheme " + model::contact_scheme_name(pair.scheme) +
                           " needs an element-face slave surface; " + def.slave + " has nodes only");
    if (nts) {
      pair.area_faces = pair.slave.faces.empty() ? exterior_faces_at(model, pair.slave.nodes)
                                                 : pair.slave.faces;
      pair.node_faces.resize(model.n_nodes());
      for (std::size_t f = 0; f < pair.area_faces.size(); ++f)
        for (std::size_t i = 0; i < pair.area_faces[f].nodes.size(); ++i)
          pair.node_faces[pair.area_faces[f].nodes[i]].push_back({int(f), int(i)});
    }
    const int p = static_cast<int>(pairs_.size());
    if (nts) {
      for (int node : pair.slave.nodes) units_.push_back({.pair = p, .node = node});
    } else {
      for (std::size_t f = 0; f < pair.slave.faces.size(); ++f)
        units_.push_back({.pair = p, .face = static_cast<int>(f)});
    }
    pairs_.push_back(std::move(pair));
  }
}

void ContactSystem::begin_step(const model::Step& step) {
  frictional_ = false;
  reference_areas_ = !step.nlgeom;
  for (std::size_t p = 0; p < pairs_.size(); ++p) {
    Pair& pair = pairs_[p];
    pair.active = p >= step.contact_pair_active.size() || step.contact_pair_active[p];
    const auto index = static_cast<std::size_t>(pair.def->interaction);
    if (index < step.interaction_behavior.size()) {  // *CHANGE SURFACE BEHAVIOR
      pair.behavior = step.interaction_behavior[index];
      pair.law = make_pressure_law(pair.behavior, pair.scheme.linear);
      pair.penalty = reference_stiffness(pair.law);
    }
    const std::optional<model::Friction>& f =
        index < step.interaction_friction.size() ? step.interaction_friction[index] : std::nullopt;
    pair.friction.reset();
    if (pair.law.kind == PressureLaw::Kind::Tied) {
      // Tied contact sticks with the *FRICTION card's slope, whatever mu says (ccx).
      pair.friction = CoulombLaw{.mu = std::numeric_limits<Real>::infinity(),
                                 .stick_slope = f ? f->stick_slope : 0};
    } else if (f) {
      pair.friction = CoulombLaw{.mu = f->mu, .stick_slope = f->stick_slope};
    }
    frictional_ |= pair.friction.has_value();
  }
}

nonlinear::ContactCriteria ContactSystem::criteria() const {
  using C = nonlinear::ContactCriteria;
  if (pairs_.empty()) return C::None;
  for (const auto& p : pairs_)
    if (p.scheme.kind == Kind::NodeToSurface || !p.scheme.linear) return C::NodeToSurface;
  return C::SurfaceToSurface;
}

model::SolutionControls ContactSystem::solution_controls(
    model::SolutionControls c, const model::ContactControls& contact) const {
  if (criteria() != nonlinear::ContactCriteria::SurfaceToSurface) return c;
  c.max_iterations = contact.itf2f;
  c.slow_increment_iterations = std::numeric_limits<int>::max();
  c.fast_increment_iterations += 12;
  return c;
}

bool ContactSystem::wants_line_search(int iteration) const {
  const bool searching = criteria() == nonlinear::ContactCriteria::SurfaceToSurface || repair_once_;
  return searching && iteration > 1 && sums_.active > 0;
}

FaceGeometry ContactSystem::slave_geometry(const Unit& unit, const VecX& u) const {
  if (unit.node < 0) return face_geometry(pairs_[unit.pair].slave.faces[unit.face], model_.mesh.coords, u);
  FaceGeometry node;
  node.topo = element::Topology::Tri3;  // unused for a node
  node.x.resize(1, 3);
  node.x.row(0) = model_.mesh.coords.row(unit.node) + u.segment<3>(3 * unit.node).transpose();
  return node;
}

ContactSystem::UnitGeometry ContactSystem::geometry(const Unit& unit, const VecX& u) const {
  const Pair& pair = pairs_[unit.pair];
  UnitGeometry g;
  g.slave = slave_geometry(unit, u);
  g.masters.reserve(unit.candidates.size());
  for (int m : unit.candidates) g.masters.push_back(face_geometry(pair.master.faces[m], model_.mesh.coords, u));
  return g;
}

FaceVec ContactSystem::slave_weights(const Unit& unit, const Point& pt) const {
  if (unit.node >= 0) return FaceVec::Ones(1);
  FaceShape s;
  face_shape(pairs_[unit.pair].slave.faces[unit.face].topo, pt.xi_s, s);
  return s.N;
}

Real ContactSystem::nodal_area(const Pair& pair, int node, const VecX& u) const {
  Real area = 0;
  for (const auto& [f, local] : pair.node_faces[node]) {
    const FaceGeometry g = face_geometry(pair.area_faces[f], model_.mesh.coords, u);
    area += face_area(g) * nodal_area_weight(g.topo, local);
  }
  return area;
}

Real ContactSystem::point_area(const Unit& unit, const Point& pt, const UnitGeometry& g,
                               const VecX& u) const {
  // Small strain measures areas, as stresses, in the reference configuration: a pressure per
  // deformed area would differ from the stress below it by the surface strain.
  const VecX& at = reference_areas_ ? no_displacement_ : u;
  // Node-to-surface: ccx's nodal share of the faces at the node (for a node-based slave
  // surface, the exterior faces of the mesh there, as ccx 2.20 computes it).
  if (unit.node < 0)
    return pt.ref_weight *
           surface_point(reference_areas_ ? slave_geometry(unit, at) : g.slave, pt.xi_s).jacobian;
  return pt.ref_weight * nodal_area(pairs_[unit.pair], unit.node, at);
}

std::vector<AabbTree> ContactSystem::master_trees(const VecX& u) const {
  std::vector<AabbTree> trees;
  for (const Pair& pair : pairs_) {
    std::vector<Box> boxes;
    for (const auto& f : pair.master.faces)
      boxes.push_back(face_box(face_geometry(f, model_.mesh.coords, u)));
    trees.emplace_back(boxes);
  }
  return trees;
}

ContactSystem::SearchRegion ContactSystem::search_region(const Unit& unit, const FaceGeometry& slave,
                                                         const VecX& u) const {
  SearchRegion r;
  if (unit.node >= 0) {
    const Pair& pair = pairs_[unit.pair];
    r.box.add(slave.x.row(0).transpose());
    for (const auto& [f, local] : pair.node_faces[unit.node])
      r.size = std::max(r.size, face_size(face_geometry(pair.area_faces[f], model_.mesh.coords, u)));
  } else {
    r.box = face_box(slave);
    r.size = face_size(slave);
    r.slave_normal = surface_point(slave, face_centre(slave.topo)).normal;
  }
  return r;
}

bool ContactSystem::faces_slave(const FaceGeometry& master, const SearchRegion& region) {
  return region.slave_normal.isZero() ||
         surface_point(master, face_centre(master.topo)).normal.dot(region.slave_normal) <=
             kOpposingCosine;
}

ContactSystem::FreshMasters ContactSystem::fresh_masters(const Unit& unit, const FaceGeometry& slave,
                                                         const AabbTree& tree, const VecX& u,
                                                         Real reach) const {
  const Pair& pair = pairs_[unit.pair];
  const SearchRegion region = search_region(unit, slave, u);
  FreshMasters fresh;
  for (int m : tree.overlapping(region.box.inflated(reach * region.size))) {
    FaceGeometry mf = face_geometry(pair.master.faces[m], model_.mesh.coords, u);
    if (!faces_slave(mf, region)) continue;
    fresh.faces.push_back(m);
    fresh.geometry.push_back(std::move(mf));
  }
  return fresh;
}

MasterFoot ContactSystem::FreshMasters::find(const Vec3& x) const {
  return find_master(x, as_candidates(geometry));
}

void ContactSystem::find_candidates(Unit& unit, const VecX& u,
                                    const std::vector<AabbTree>& trees) const {
  const Pair& pair = pairs_[unit.pair];
  const SearchRegion region = search_region(unit, slave_geometry(unit, u), u);
  // Master faces within twice the unit's own size: whatever can touch it within the increment
  // (gaps up to 1 % of a body 200 elements across), and no more, however coarse the surfaces
  // are elsewhere. A point that slides farther is caught by missed_contact.
  unit.candidates.clear();
  if (!pair.active) return;
  for (int m : trees[unit.pair].overlapping(region.box.inflated(kCandidateMargin * region.size)))
    if (faces_slave(face_geometry(pair.master.faces[m], model_.mesh.coords, u), region))
      unit.candidates.push_back(m);
}

void ContactSystem::build_points(Unit& unit, const VecX& u, const OldStates& old,
                                 const VecX* increment_start) const {
  const Pair& pair = pairs_[unit.pair];
  const UnitGeometry g = geometry(unit, u);
  // The relative motion friction sees starts where the increment started.
  const std::optional<UnitGeometry> start =
      increment_start ? std::optional<UnitGeometry>(geometry(unit, *increment_start))
                      : std::nullopt;
  unit.points.clear();
  if (unit.node >= 0) {
    // A node over an edge or vertex of the master surface presses on each face there with its
    // share of the nodal area (find_tied_masters); pair_point keeps each share on its face.
    const std::vector<MasterFoot> feet =
        find_tied_masters(g.slave.x.row(0).transpose(), as_candidates(g.masters));
    const int shares = std::max(1, static_cast<int>(feet.size()));
    for (int k = 0; k < shares; ++k)
      unit.points.push_back({.ref_weight = Real(1) / shares,
                             .pairing = {.master = feet.empty() ? -1 : feet[k].candidate}});
  } else {
    const SurfaceFace& face = pair.slave.faces[unit.face];
    const std::vector<SlavePointSeed> seeds =
        pair.scheme.kind == Kind::Gauss ? gauss_points(face.element_type, face.topo)
                                        : gauss_cut_points(g.slave, g.masters, pair.scheme.points);
    for (const auto& s : seeds)
      unit.points.push_back({.xi_s = s.xi, .ref_weight = s.ref_weight,
                             .pairing = {.master = s.master}});
  }
  // Initial overlaps are ramped out over the rest of step 1 (ccx: face-to-face re-ramps at
  // every increment, node-to-face over the first increment only). Face-to-face also closes
  // initial gaps below 1/K (a length numerically) in the first increment: meshes of touching
  // bodies are not quite touching at every point. Later increments see the real gaps, so a
  // redone or split increment does not carry that offset into the final state.
  const bool ramp = ctx_.step == 1 && (pair.scheme.kind != Kind::NodeToSurface || ctx_.increment == 1);
  const bool close_gaps = ctx_.step == 1 && ctx_.increment == 1 &&
                          pair.scheme.kind != Kind::NodeToSurface && pair.behavior.stiffness > 0;
  const Real theta = ctx_.fraction_start;
  for (Point& pt : unit.points) {
    pt.overlap0 = pt.closure = 0;
    pt.pairing = pair_point(unit, g, pt, u);
    pt.frozen_master = pt.pairing.master;
    if (pt.pairing.master < 0) continue;
    if (start) {  // a linear variant frozen again: its offsets from its gap at the start
      freeze(unit, g, pt, u);
      pt.frozen_gap = pt.pairing.gap;
      pt.frozen_relative = frozen_relative_position(
          start->slave.x, start->masters[pt.frozen_master].x, pt.frozen);
      const Real gap0 = pt.frozen_relative.dot(pt.frozen.normal);
      if (ramp && gap0 < 0 && theta < 1) pt.overlap0 = gap0 / (1 - theta);
      if (close_gaps && gap0 >= 0 && gap0 < 1 / pair.behavior.stiffness) pt.closure = gap0;
      continue;
    }
    const Real gap = pt.frozen_gap = pt.pairing.gap;
    if (ramp && gap < 0 && theta < 1) pt.overlap0 = gap / (1 - theta);
    if (close_gaps && gap >= 0 && gap < 1 / pair.behavior.stiffness) pt.closure = gap;
    if (!pair.scheme.linear && (pt.overlap0 != 0 || pt.closure != 0)) {
      pt.pairing = pair_point(unit, g, pt, u);  // existence with the offsets applied
      pt.frozen_master = pt.pairing.master;
      if (pt.pairing.master < 0) continue;
    }
    freeze(unit, g, pt, u);
    pt.frozen_relative =
        frozen_relative_position(g.slave.x, g.masters[pt.frozen_master].x, pt.frozen);
  }
  // The slip history moves over: per slave node, or interpolated over the slave face.
  if (old.xi.empty()) return;
  std::vector<Vec2> xi;
  for (const Point& pt : unit.points) xi.push_back(pt.xi_s);
  const MatX moved =
      unit.node >= 0 ? MatX(old.states.colwise().mean())  // the node's shares, averaged
                     : transfer_states(pair.slave.faces[unit.face].topo, old.xi, old.states,
                                       old.corners, xi);
  for (std::size_t k = 0; k < unit.points.size(); ++k) {
    Point& pt = unit.points[k];
    pt.committed.friction = pt.trial.friction =
        unpack(moved.row(static_cast<Index>(unit.node >= 0 ? 0 : k)).transpose());
  }
}

std::vector<ContactSystem::OldStates> ContactSystem::committed_states() const {
  std::vector<OldStates> old(units_.size());
  if (!frictional_) return old;
  // Per pair: the corner states of every face, summed at the corner nodes.
  std::vector<std::map<int, std::pair<StateVector, int>>> at_node(pairs_.size());
  for (std::size_t k = 0; k < units_.size(); ++k) {
    const Unit& unit = units_[k];
    OldStates& o = old[k];
    for (const Point& pt : unit.points) {
      if (pt.frozen_master < 0) continue;  // no master under it: it carried no state
      o.xi.push_back(pt.xi_s);
      o.states.conservativeResize(o.states.rows() + 1, 6);
      o.states.row(o.states.rows() - 1) = pack(pt.committed.friction).transpose();
    }
    if (unit.node >= 0 || o.xi.empty()) continue;
    const SurfaceFace& face = pairs_[unit.pair].slave.faces[unit.face];
    o.corners = corner_states(face.topo, o.xi, o.states);
    for (Index c = 0; c < o.corners.rows(); ++c) {
      auto& [sum, count] = at_node[unit.pair][face.nodes[c]];
      if (count == 0) sum.setZero();
      sum += o.corners.row(c).transpose();
      ++count;
    }
  }
  for (std::size_t k = 0; k < units_.size(); ++k) {
    const Unit& unit = units_[k];
    if (unit.node >= 0 || old[k].xi.empty()) continue;
    const SurfaceFace& face = pairs_[unit.pair].slave.faces[unit.face];
    for (Index c = 0; c < old[k].corners.rows(); ++c) {
      const auto& [sum, count] = at_node[unit.pair].at(face.nodes[c]);
      old[k].corners.row(c) = (sum / count).transpose();
    }
  }
  return old;
}

ContactSystem::Pairing ContactSystem::pair_point(const Unit& unit, const UnitGeometry& g,
                                                 const Point& pt, const VecX& u) const {
  const Vec3 xs = g.slave.x.transpose() * slave_weights(unit, pt);
  MasterFoot best;
  // A Gauss-Cut point first tries the master face it was cut from (or paired with before).
  const int previous = pt.pairing.master;
  if (previous >= 0 && previous < static_cast<int>(g.masters.size())) {
    const FaceGeometry& m = g.masters[previous];
    const ClosestPoint f = project_onto_face(m, xs, face_centre(m.topo));
    if (f.converged && inside_reference_face(m.topo, f.xi, kEdgeTolerance)) best = {previous, f};
  }
  if (best.candidate < 0) best = find_master(xs, as_candidates(g.masters));
  Pairing p;
  if (best.candidate < 0) return p;
  p.master = best.candidate;
  p.xi_m = best.foot.xi;
  p.gap = best.foot.gap;
  const Pair& pair = pairs_[unit.pair];
  if (!pair.scheme.linear) {
    // Nonlinear variants: the contact element exists when the point is within the creation
    // clearance (c0 sqrt(A)), judged at pairing and kept until the next pairing, and so is
    // its area (as ccx regenerates its node-to-face elements).
    p.area = point_area(unit, pt, g, u);
    // A node's clearance is its whole area's, whatever share of it this point carries.
    const Real area = unit.node >= 0 ? p.area / pt.ref_weight : p.area;
    p.exists = is_active(pair.law, -(p.gap + gap_offset(pt)), creation_clearance(pair.behavior, area));
  }
  return p;
}

void ContactSystem::freeze(const Unit& unit, const UnitGeometry& g, Point& pt, const VecX& u) const {
  const FaceGeometry& m = g.masters[pt.frozen_master];
  FaceShape s;
  face_shape(m.topo, pt.pairing.xi_m, s);
  pt.frozen.master_weights = s.N;
  pt.frozen.normal = surface_point(m, pt.pairing.xi_m).normal;
  pt.frozen.slave_weights = slave_weights(unit, pt);
  pt.frozen.area = point_area(unit, pt, g, u);
}

void ContactSystem::begin_increment(const VecX& u, const IncrementContext& ctx, int threads,
                                    const VecX* predicted) {
  ctx_ = ctx;
  evaluations_ = 0;
  repair_once_ = false;
  stabilisation_ = 0;  // springs belong to one increment
  const bool ahead = predicted && *predicted != u &&
                     std::any_of(pairs_.begin(), pairs_.end(),
                                 [](const Pair& p) { return p.scheme.linear; });
  const std::vector<AabbTree> trees = master_trees(u);
  const std::vector<AabbTree> trees_ahead =
      ahead ? master_trees(*predicted) : std::vector<AabbTree>{};
  const std::vector<OldStates> old = committed_states();
  parallel_chunks(units_.size(), threads, [&](std::size_t begin, std::size_t end, int) {
    for (std::size_t k = begin; k < end; ++k) {
      // The nonlinear variants pair as they go, from the converged state.
      if (ahead && pairs_[units_[k].pair].scheme.linear) {
        find_candidates(units_[k], *predicted, trees_ahead);
        build_points(units_[k], *predicted, old[k], &u);
      } else {
        find_candidates(units_[k], u, trees);
        build_points(units_[k], u, old[k], nullptr);
      }
    }
  });
  build_groups();
}

void ContactSystem::refreeze(const VecX& u, const VecX& increment_start, int threads) {
  const std::vector<AabbTree> trees = master_trees(u);
  const std::vector<OldStates> old = committed_states();
  parallel_chunks(units_.size(), threads, [&](std::size_t begin, std::size_t end, int) {
    for (std::size_t k = begin; k < end; ++k) {
      if (!pairs_[units_[k].pair].scheme.linear) continue;  // they pair as they go
      find_candidates(units_[k], u, trees);
      build_points(units_[k], u, old[k], &increment_start);
    }
  });
  build_groups();
}

void ContactSystem::build_groups() {
  // The linear variants need one group per master face a point is frozen to; the others one
  // per candidate, since their points may move to any candidate during the increment.
  group_nodes_.clear();
  for (Unit& unit : units_) {
    const Pair& pair = pairs_[unit.pair];
    std::vector<char> used(unit.candidates.size(), !pair.scheme.linear);
    for (const Point& pt : unit.points)
      if (pt.pairing.master >= 0) used[pt.pairing.master] = 1;
    unit.groups.assign(unit.candidates.size(), -1);
    const std::vector<int> slave_nodes =
        unit.node >= 0 ? std::vector<int>{unit.node} : pair.slave.faces[unit.face].nodes;
    for (std::size_t c = 0; c < unit.candidates.size(); ++c) {
      if (!used[c]) continue;
      unit.groups[c] = static_cast<int>(group_nodes_.size());
      std::vector<int> nodes = slave_nodes;
      const auto& mn = pair.master.faces[unit.candidates[c]].nodes;
      nodes.insert(nodes.end(), mn.begin(), mn.end());
      group_nodes_.push_back(std::move(nodes));
    }
  }
  contributions_.assign(group_nodes_.size(), {});
  for (std::size_t k = 0; k < group_nodes_.size(); ++k) {
    const int n = 3 * static_cast<int>(group_nodes_[k].size());
    contributions_[k].K.setZero(n, n);
    contributions_[k].f_int.setZero(n);
  }
}

void ContactSystem::Sums::add(const Sums& o) {
  force.abs_sum += o.force.abs_sum;
  force.components += o.force.components;
  active += o.active;
  pressing += o.pressing;
  sticking += o.sticking;
  slipping += o.slipping;
  contact_force += o.contact_force;
  stabilisation_force += o.stabilisation_force;
  stabilisation_energy += o.stabilisation_energy;
  stabilisation_pull += o.stabilisation_pull;
  spring_stiffness += o.spring_stiffness;
  min_open_gap = std::min(min_open_gap, o.min_open_gap);
}

ContactSystem::Sums ContactSystem::evaluate_unit(Unit& unit, const VecX& u, Repairing repairing) {
  const Pair& pair = pairs_[unit.pair];
  for (int gi : unit.groups) {
    if (gi < 0) continue;
    contributions_[gi].K.setZero();
    contributions_[gi].f_int.setZero();
  }
  Sums sums;
  if (unit.points.empty()) return sums;
  const UnitGeometry g = geometry(unit, u);
  const PressureLaw& law = pair.law;
  // The stabilisation spring: linear in the change of the frozen gap, in tension too.
  PressureLaw spring_law;
  spring_law.kind = PressureLaw::Kind::Tied;
  spring_law.stiffness = stabilisation_ * pair.penalty;
  auto add = [&](const PointResponse& r, int master) {
    GroupContribution& c = contributions_[unit.groups[master]];
    c.K += r.K;
    c.f_int += r.f_int;
    sums.force.abs_sum += r.f_int.cwiseAbs().sum();
    sums.force.components += r.f_int.size();
  };
  PointResponse r;
  // The contact response of one point into its trial state; true when it is active.
  auto contact_response = [&](Point& pt) {
    PointState& s = pt.trial;
    if (repairing == Repairing::All ||
        (repairing == Repairing::WithoutElement && !pt.pairing.exists))
      pt.pairing = pair_point(unit, g, pt, u);
    Pairing& p = pt.pairing;
    if (p.master < 0) return false;
    if (pair.scheme.linear) {
      pt.frozen.gap_offset = gap_offset(pt);
      frozen_point_response(g.slave.x, g.masters[p.master].x, pt.frozen, law, 0, r);
      s.area = pt.frozen.area;
    } else {
      if (!p.exists) return false;
      Vec2 xi = p.xi_m;
      if (!sliding_point_response(g.slave.x, slave_weights(unit, pt), g.masters[p.master], xi,
                                  p.area, gap_offset(pt), law, kNoClearanceLimit, r))
        return false;
      p.xi_m = xi;
      s.area = p.area;
    }
    s.gap = r.gap;
    if (!r.active) return false;
    s.active = true;
    s.pressure = r.pressure.pressure;
    s.energy = r.pressure.energy * s.area;
    add(r, p.master);
    ++sums.active;
    if (s.pressure > 0) {
      ++sums.pressing;
      sums.contact_force += s.pressure * s.area;
    }
    return true;
  };
  for (Point& pt : unit.points) {
    pt.trial = {};
    Real spring_gap = -1;  // geometric gap along the spring's frozen normal
    if (stabilisation_ > 0 && pt.frozen_master >= 0) {
      FrozenPoint spring = pt.frozen;
      spring.gap_offset = -pt.frozen_gap;
      frozen_point_response(g.slave.x, g.masters[pt.frozen_master].x, spring, spring_law, 0, r);
      add(r, pt.frozen_master);
      sums.stabilisation_force += std::abs(r.pressure.pressure) * spring.area;
      sums.stabilisation_pull -= r.pressure.pressure * spring.area;
      sums.stabilisation_energy += r.pressure.energy * spring.area;
      sums.spring_stiffness += spring_law.stiffness * spring.area;
      spring_gap = r.gap + pt.frozen_gap;
    }
    // Points that press carry the load; the others (open, or in a law's tension tail) still
    // have to close.
    const bool pressed = contact_response(pt);
    if (pt.trial.pressure <= 0 && spring_gap > 0)
      sums.min_open_gap = std::min(sums.min_open_gap, spring_gap);
    if (pair.friction && pt.frozen_master >= 0) add_point_friction(unit, g, pt, pressed ? &r : nullptr, sums);
  }
  if (unit.node >= 0) {  // a node counts once, however many faces its shares press on
    sums.active = std::min(sums.active, 1);
    sums.pressing = std::min(sums.pressing, 1);
    sums.slipping = std::min(sums.slipping, 1);
    sums.sticking = sums.slipping > 0 ? 0 : std::min(sums.sticking, 1);
  }
  return sums;
}

void ContactSystem::add_point_friction(Unit& unit, const UnitGeometry& g, Point& pt,
                                       const PointResponse* normal, Sums& sums) {
  // On the frozen pairing of the increment (its normal and foot point): the relative
  // displacement since the start, the normal force of the current evaluation.
  PointState& s = pt.trial;
  const FaceCoords& master_x = g.masters[pt.frozen_master].x;
  const Vec3 moved = frozen_relative_position(g.slave.x, master_x, pt.frozen) - pt.frozen_relative;
  const Real area = s.active ? s.area : pt.frozen.area;
  const Real normal_force = s.active ? s.pressure * s.area : 0;
  // The committed state is the one the increment started from: commit() comes at its end.
  const TangentialResponse t =
      coulomb_response(*pairs_[unit.pair].friction, pt.committed.friction, moved,
                       pt.frozen.normal, area, normal_force);
  s.friction = t.state;
  s.shear = area > 0 ? Vec3(t.force / area) : Vec3::Zero();
  s.slipping = t.slipping;
  if (!s.active) return;
  (t.slipping ? sums.slipping : sums.sticking) += 1;
  // The slip force's coupling to the normal force needs the normal response on these faces.
  PointResponse none;
  const bool coupled = normal && pt.pairing.master == pt.frozen_master;
  const int n_dofs = 3 * static_cast<int>(pt.frozen.slave_weights.size() + master_x.rows());
  PointDofVec f = PointDofVec::Zero(n_dofs);
  PointDofMat K = PointDofMat::Zero(n_dofs, n_dofs);
  add_friction(pt.frozen, t.d_force_d_s, t.force, t.d_force_d_normal, coupled ? *normal : none,
               area, f, K);
  GroupContribution& c = contributions_[unit.groups[pt.frozen_master]];
  c.K += K;
  c.f_int += f;
  sums.force.abs_sum += f.cwiseAbs().sum();
}

void ContactSystem::update(const VecX& u, int threads) {
  ++evaluations_;
  std::vector<Sums> sums(units_.size());
  parallel_chunks(units_.size(), threads, [&](std::size_t begin, std::size_t end, int) {
    for (std::size_t k = begin; k < end; ++k) {
      Unit& unit = units_[k];
      const Pair& pair = pairs_[unit.pair];
      Repairing repairing = Repairing::None;
      if (!pair.scheme.linear && !pair.def->small_sliding) {
        if (repair_once_)
          repairing = evaluations_ == 1 ? Repairing::All : Repairing::WithoutElement;
        else if (evaluations_ > 1)
          repairing = evaluations_ <= kRepairEvaluations ? Repairing::All : Repairing::WithoutElement;
      }
      sums[k] = evaluate_unit(unit, u, repairing);
    }
  });
  sums_ = {};
  for (const Sums& s : sums) sums_.add(s);
  for (const auto& c : contributions_)
    if (!c.f_int.allFinite() || !c.K.allFinite())
      throw SolverError("contact: non-finite contact force or stiffness");
}

void ContactSystem::set_stabilisation(Real factor) {
  if (factor == stabilisation_) return;
  stabilisation_ = factor;
  pair_again();
}

Real ContactSystem::step_fraction_to_contact(const VecX& u, const VecX& du) const {
  struct Move {
    Real from, to;  // gap along the frozen normal before and after the step
    bool pressing;
  };
  std::vector<Move> moves;
  const VecX stepped = u + du;
  for (const Unit& unit : units_) {
    if (unit.points.empty() || pairs_[unit.pair].scheme.linear) continue;
    const UnitGeometry before = geometry(unit, u), after = geometry(unit, stepped);
    const auto gap = [](const UnitGeometry& g, const Point& pt) {
      return pt.frozen.normal.dot(
          frozen_relative_position(g.slave.x, g.masters[pt.frozen_master].x, pt.frozen));
    };
    for (const Point& pt : unit.points)
      if (pt.frozen_master >= 0)
        moves.push_back({gap(before, pt), gap(after, pt), pt.trial.pressure > 0});
  }
  Real deepest = 0;
  for (const Move& m : moves)
    if (m.pressing) deepest = std::max({deepest, -m.from, -m.to});
  Real fraction = 1;
  for (const Move& m : moves)
    if (!m.pressing && m.from > 0 && m.to < -deepest)
      fraction = std::min(fraction, (m.from + deepest) / (m.from - m.to));
  return fraction;
}

std::optional<Real> ContactSystem::approach_ratio() const {
  const Real closing = -sums_.stabilisation_pull;
  if (sums_.pressing > 0 || closing <= 0 || sums_.spring_stiffness <= 0 ||
      !std::isfinite(sums_.min_open_gap))
    return std::nullopt;
  const Real d = closing / sums_.spring_stiffness;
  return d / (d + 1.2 * sums_.min_open_gap);
}

Real ContactSystem::stabilisation_share() const {
  const Real total = sums_.stabilisation_force + sums_.contact_force;
  return total > 0 ? sums_.stabilisation_force / total : 0;
}

ForceMeasure ContactSystem::add_to(const assembly::AssemblyPlan& plan, const VecX& prescribed_step,
                                   assembly::ReducedSystem& system, VecX& internal_force) const {
  // Contact groups act like elements: scattered with the same dof reduction, part of the
  // reaction forces and of the average force.
  std::vector<const MatX*> K(contributions_.size());
  std::vector<const VecX*> f(contributions_.size());
  std::vector<VecX> minus_f(contributions_.size());
  for (std::size_t g = 0; g < contributions_.size(); ++g) {
    const GroupContribution& c = contributions_[g];
    minus_f[g] = -c.f_int;
    K[g] = &c.K;
    f[g] = &minus_f[g];
    const auto& nodes = group_nodes_[g];
    for (std::size_t a = 0; a < nodes.size(); ++a)
      internal_force.segment<3>(3 * nodes[a]) += c.f_int.segment<3>(3 * a);
  }
  if (sums_.slipping > 0) system.skew.assign(system.values.size(), 0.0);  // unsymmetric slip
  assembly::scatter_groups(plan, prescribed_step, K, f, system);
  return sums_.force;
}

namespace {

/// A linear variant whose frozen gaps differ from fresh projections by more than this
/// fraction of the largest overclosure redoes the increment smaller when freezing its geometry
/// again at the solution does not bring the drift below it.
constexpr Real kDriftTolerance = 0.1;

/// Above this drift a converged increment freezes its geometry again at its solution and goes
/// on: it costs a few iterations, and the drift is a pressure error of that order (sliding
/// cylinder: 7.4e-2 of p0 at 0.1, 2.9e-3 at 0.01, 2.8e-3 at 1e-3 with three times the
/// refreezes).
constexpr Real kRefreezeTolerance = 0.01;

/// Gaps are differences of coordinates: a drift below this share of the slave coordinates is
/// round-off, not drift (a tied interface in pure shear has no overclosure to compare with).
constexpr Real kGapRoundOff = 1e-12;

/// How far (in slave face sizes) the drift check looks for the master face under an active point
/// that has none near it: a frozen geometry can hold a point in contact far from the master.
constexpr Real kFarReach = 8;

/// A missed contact is redone at half the increment until the sliding of one increment stays
/// within the search neighbourhood.
constexpr Real kMissedRedoFactor = 0.5;

/// How much smaller: the drift grows about with the square of the increment (the frozen normal
/// is off by the sliding, and so is the gap along it: measured 0.37 -> 0.11 for a halved
/// increment on the Hertz model), so one redo aims at 80 % of the tolerance.
Real drift_redo_factor(Real drift) {
  return std::clamp(std::sqrt(0.8 * kDriftTolerance / drift), 0.25, 0.75);
}

}  // namespace

Acceptance ContactSystem::accept(const VecX& u, bool check_drift) const {
  const std::vector<AabbTree> trees = master_trees(u);
  if (const MissedContact missed = missed_contact(u, trees); missed.depth > 0) {
    std::ostringstream reason;
    reason << "contact search missed a penetration of " << missed.depth << " at ("
           << missed.where.x() << ", " << missed.where.y() << ", " << missed.where.z()
           << "): the bodies slid farther in the increment than the search looked";
    return {.accepted = false, .redo_factor = kMissedRedoFactor, .reason = reason.str(),
            .required = true};
  }
  if (const MissedContact unheld = unheld_penetration(u); unheld.depth > 0) {
    std::ostringstream reason;
    reason << "a slave point without contact element penetrates its master by " << unheld.depth
           << " at (" << unheld.where.x() << ", " << unheld.where.y() << ", "
           << unheld.where.z() << ")";
    return {.accepted = false, .redo_factor = kMissedRedoFactor, .reason = reason.str(),
            .required = true, .pair_again = true};
  }
  if (!check_drift || criteria() != nonlinear::ContactCriteria::SurfaceToSurface) return {};
  const Real drift = frozen_drift(u, trees);
  if (drift <= kRefreezeTolerance) return {};
  return {.accepted = false, .redo_factor = drift_redo_factor(drift),
          .reason = "frozen contact geometry drifted: gaps off by " + std::to_string(drift) +
                    " of the largest overclosure", .refreeze_only = drift <= kDriftTolerance};
}

void ContactSystem::pair_again() {
  repair_once_ = true;
  evaluations_ = 0;
}

void ContactSystem::commit() {
  for (Unit& unit : units_)
    for (Point& pt : unit.points) pt.committed = pt.trial;
}

void ContactSystem::roll_back() {
  for (Unit& unit : units_)
    for (Point& pt : unit.points) pt.trial = pt.committed;
}

Real ContactSystem::total_normal_force() const {
  Real total = 0;
  for (const Unit& unit : units_)
    for (const Point& pt : unit.points)
      if (pt.committed.active) total += pt.committed.pressure * pt.committed.area;
  return total;
}

Real ContactSystem::max_pressure() const {
  Real p = 0;
  for (const Unit& unit : units_)
    for (const Point& pt : unit.points)
      if (pt.committed.active) p = std::max(p, pt.committed.pressure);
  return p;
}

Real ContactSystem::frozen_drift(const VecX& u, const std::vector<AabbTree>& trees) const {
  Real drift = 0, overclosure = 0, coordinates = 0;
  for (const Unit& unit : units_) {
    if (!pairs_[unit.pair].scheme.linear) continue;
    bool any = false;
    for (const Point& pt : unit.points) any |= pt.trial.active;
    if (!any) continue;
    const FaceGeometry slave = slave_geometry(unit, u);
    // Fresh projections on whatever master faces are under the points now, candidates or not;
    // a point the frozen geometry holds in contact may be far from the master by now.
    const FreshMasters near = fresh_masters(unit, slave, trees[unit.pair], u);
    std::optional<FreshMasters> far;
    coordinates = std::max(coordinates, slave.x.cwiseAbs().maxCoeff());
    for (const Point& pt : unit.points) {
      if (!pt.trial.active) continue;
      overclosure = std::max(overclosure, -pt.trial.gap);
      const Vec3 xs = slave.x.transpose() * pt.frozen.slave_weights;
      MasterFoot fresh = near.find(xs);
      if (fresh.candidate < 0) {
        if (!far) far = fresh_masters(unit, slave, trees[unit.pair], u, kFarReach);
        fresh = far->find(xs);
      }
      if (fresh.candidate < 0) continue;  // slid beyond the master surface's edge
      drift = std::max(drift, std::abs(pt.trial.gap - (fresh.foot.gap + gap_offset(pt))));
    }
  }
  if (drift <= kGapRoundOff * coordinates) return 0;
  return overclosure > 0 ? drift / overclosure : 0;
}

Real ContactSystem::penetration_tolerance(Real coordinates) const {
  Real overclosure = 0;
  for (const Unit& unit : units_)
    for (const Point& pt : unit.points)
      if (pt.trial.active) overclosure = std::max(overclosure, -pt.trial.gap);
  return std::max(kDriftTolerance * overclosure, kGapRoundOff * coordinates);
}

MissedContact ContactSystem::missed_contact(const VecX& u,
                                            const std::vector<AabbTree>& trees) const {
  Real coordinates = 0;
  MissedContact worst;
  for (const Unit& unit : units_) {
    if (!pairs_[unit.pair].active) continue;
    const FaceGeometry slave = slave_geometry(unit, u);
    coordinates = std::max(coordinates, slave.x.cwiseAbs().maxCoeff());
    const FreshMasters fresh = fresh_masters(unit, slave, trees[unit.pair], u);
    const auto is_candidate = [&unit](int m) {
      return std::find(unit.candidates.begin(), unit.candidates.end(), m) != unit.candidates.end();
    };
    // Only a face the increment did not offer can hold a missed point.
    if (std::all_of(fresh.faces.begin(), fresh.faces.end(), is_candidate)) continue;
    const auto check = [&](const Vec3& xs, Real offset) {
      const MasterFoot foot = fresh.find(xs);
      if (foot.candidate < 0 || is_candidate(fresh.faces[foot.candidate])) return;
      const Real depth = -(foot.foot.gap + offset);
      if (depth > worst.depth) worst = {.depth = depth, .where = xs};
    };
    for (const Point& pt : unit.points)
      if (!pt.trial.active) check(slave.x.transpose() * slave_weights(unit, pt), gap_offset(pt));
    // A face may have no points at all where its increment offered no master face.
    if (unit.node < 0)
      for (Index i = 0; i < slave.x.rows(); ++i) check(slave.x.row(i).transpose(), 0);
  }
  return worst.depth > penetration_tolerance(coordinates) ? worst : MissedContact{};
}

MissedContact ContactSystem::unheld_penetration(const VecX& u) const {
  Real coordinates = 0;
  MissedContact worst;
  for (const Unit& unit : units_) {
    const Pair& pair = pairs_[unit.pair];
    if (!pair.active || pair.scheme.linear || unit.points.empty()) continue;
    const UnitGeometry g = geometry(unit, u);
    coordinates = std::max(coordinates, g.slave.x.cwiseAbs().maxCoeff());
    for (const Point& pt : unit.points) {
      if (pt.trial.active) continue;
      const Vec3 xs = g.slave.x.transpose() * slave_weights(unit, pt);
      const MasterFoot foot = find_master(xs, as_candidates(g.masters));
      if (foot.candidate < 0) continue;
      const Real depth = -(foot.foot.gap + gap_offset(pt));
      if (depth > worst.depth) worst = {.depth = depth, .where = xs};
    }
  }
  return worst.depth > penetration_tolerance(coordinates) ? worst : MissedContact{};
}

void ContactSystem::write_output(const VecX& u, output::Frame& frame) const {
  std::vector<char> on_slave(model_.n_nodes(), 0), inside(model_.n_nodes(), 0);
  frame.contact_points.clear();
  frame.n_active_contact = 0;
  const std::vector<AabbTree> trees = master_trees(u);
  for (const Unit& unit : units_) {
    const Pair& pair = pairs_[unit.pair];
    const UnitGeometry g = geometry(unit, u);
    for (const Point& pt : unit.points) {
      output::ContactPointRecord r;
      r.pair = unit.pair;
      if (unit.node >= 0) {
        r.slave_node = unit.node;
      } else {
        r.slave_element = pair.slave.faces[unit.face].element;
        r.slave_face = pair.slave.faces[unit.face].face;
      }
      r.xi = pt.xi_s;
      r.x = g.slave.x.transpose() * slave_weights(unit, pt);
      r.active = pt.committed.active;
      r.clearance = pt.committed.gap;
      r.pressure = pt.committed.pressure;
      r.area = pt.committed.area;
      r.energy = pt.committed.energy;
      if (pair.friction && pt.frozen_master >= 0) {
        // ccx's output directions: t1 the global x (z when the normal is x) in the tangent
        // plane, t2 = n x t1.
        const Vec3& n = pt.frozen.normal;
        const Vec3 axis = std::abs(std::abs(n.x()) - 1) < 1.5e-6 ? Vec3::UnitZ() : Vec3::UnitX();
        const Vec3 t1 = (axis - axis.dot(n) * n).normalized(), t2 = n.cross(t1);
        const Vec3& t = pt.committed.friction.tangential;
        r.slip = Vec2(t.dot(t1), t.dot(t2));
        r.shear = Vec2(pt.committed.shear.dot(t1), pt.committed.shear.dot(t2));
        r.sticking = pt.committed.active && !pt.committed.slipping;
      }
      frame.contact_points.push_back(r);
    }
    if (unit.node >= 0 && unit.points.size() > 1) {
      const auto shares = frame.contact_points.end() - static_cast<std::ptrdiff_t>(unit.points.size());
      *shares = output::merged_record(std::span(shares, frame.contact_points.end()));
      frame.contact_points.erase(shares + 1, frame.contact_points.end());
    }
    if (unit.node >= 0) frame.n_active_contact += frame.contact_points.back().active;
    else
      for (const Point& pt : unit.points) frame.n_active_contact += pt.committed.active;
    // Slave nodes that project onto no master face get no extrapolated values (thesis §4.3.2).
    if (unit.node >= 0) {
      on_slave[unit.node] = 1;
      inside[unit.node] |= !unit.points.empty() && unit.points.front().pairing.master >= 0;
      continue;
    }
    // Where the node is now: the increment's candidates may have slid away from it.
    const FreshMasters masters = fresh_masters(unit, g.slave, trees[unit.pair], u);
    const auto& nodes = pair.slave.faces[unit.face].nodes;
    for (std::size_t i = 0; i < nodes.size(); ++i) {
      on_slave[nodes[i]] = 1;
      if (!inside[nodes[i]]) inside[nodes[i]] = masters.find(g.slave.x.row(i).transpose()).candidate >= 0;
    }
  }
  std::vector<bool> outside(model_.n_nodes(), false);
  for (int n = 0; n < model_.n_nodes(); ++n) outside[n] = on_slave[n] && !inside[n];
  frame.contact_nodal = contact_nodal_values(model_, frame.contact_points, outside);
}

}  // namespace kontakt::contact
