#include "contact/contact_system.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "contact/master_search.hpp"
#include "contact/slave_points.hpp"
#include "core/error.hpp"
#include "core/parallel.hpp"

namespace kontakt::contact {

using Kind = model::ContactScheme::Kind;

namespace {

/// Node-to-surface pairing is redone in the first evaluations of an increment and then frozen
/// (ccx: iterations up to 8), so the active set can settle.
constexpr int kRepairEvaluations = 8;
constexpr Real kNoClearanceLimit = std::numeric_limits<Real>::infinity();

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

ContactSystem::ContactSystem(const model::Model& model) : model_(model) {
  for (const auto& def : model.contact_pairs) {
    Pair pair;
    pair.def = &def;
    pair.scheme = def.scheme;
    pair.behavior = model.interactions.at(def.interaction).behavior;
    pair.law = make_pressure_law(pair.behavior, pair.scheme.linear);
    pair.slave = make_contact_surface(model, model.surfaces.at(def.slave));
    pair.master = make_contact_surface(model, model.surfaces.at(def.master));
    if (pair.master.faces.empty())
      throw InputError(def.where, "*CONTACT PAIR",
                       "master surface " + def.master + " has no element faces");
    const bool nts = pair.scheme.kind == Kind::NodeToSurface;
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

nonlinear::ContactCriteria ContactSystem::criteria() const {
  using C = nonlinear::ContactCriteria;
  if (pairs_.empty()) return C::None;
  for (const auto& p : pairs_)
    if (p.scheme.kind == Kind::NodeToSurface || !p.scheme.linear) return C::NodeToSurface;
  return C::SurfaceToSurface;
}

ContactSystem::UnitGeometry ContactSystem::geometry(const Unit& unit, const VecX& u) const {
  const Pair& pair = pairs_[unit.pair];
  UnitGeometry g;
  if (unit.node >= 0) {
    g.slave.topo = element::Topology::Tri3;  // unused for a node
    g.slave.x.resize(1, 3);
    g.slave.x.row(0) = model_.mesh.coords.row(unit.node) + u.segment<3>(3 * unit.node).transpose();
  } else {
    g.slave = face_geometry(pair.slave.faces[unit.face], model_.mesh.coords, u);
  }
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
  // Node-to-surface: ccx's nodal share of the faces at the node (for a node-based slave
  // surface, the exterior faces of the mesh there, as ccx 2.20 computes it).
  if (unit.node < 0) return pt.ref_weight * surface_point(g.slave, pt.xi_s).jacobian;
  return nodal_area(pairs_[unit.pair], unit.node, u);
}

void ContactSystem::find_candidates(Unit& unit, const VecX& u, const std::vector<AabbTree>& trees,
                                    const std::vector<Real>& margins) const {
  const Pair& pair = pairs_[unit.pair];
  Box box;
  Vec3 slave_normal = Vec3::Zero();
  if (unit.node >= 0) {
    box.add(model_.mesh.coords.row(unit.node).transpose() + u.segment<3>(3 * unit.node));
  } else {
    const FaceGeometry f = face_geometry(pair.slave.faces[unit.face], model_.mesh.coords, u);
    box = face_box(f);
    slave_normal = surface_point(f, face_centre(f.topo)).normal;
  }
  unit.candidates.clear();
  for (int m : trees[unit.pair].overlapping(box.inflated(margins[unit.pair]))) {
    if (unit.node < 0) {
      // Surface-to-surface: only master faces facing the slave face.
      const FaceGeometry mf = face_geometry(pair.master.faces[m], model_.mesh.coords, u);
      if (surface_point(mf, face_centre(mf.topo)).normal.dot(slave_normal) > kOpposingCosine) continue;
    }
    unit.candidates.push_back(m);
  }
}

void ContactSystem::build_points(Unit& unit, const VecX& u) const {
  const Pair& pair = pairs_[unit.pair];
  const UnitGeometry g = geometry(unit, u);
  unit.points.clear();
  if (unit.node >= 0) {
    unit.points.push_back({.ref_weight = nodal_area(pair, unit.node, u)});
  } else {
    const SurfaceFace& face = pair.slave.faces[unit.face];
    const std::vector<SlavePointSeed> seeds =
        pair.scheme.kind == Kind::Gauss ? gauss_points(face.element_type, face.topo)
                                        : gauss_cut_points(g.slave, g.masters, pair.scheme.points);
    for (const auto& s : seeds)
      unit.points.push_back({.xi_s = s.xi, .ref_weight = s.ref_weight, .master = s.master});
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
    pair_point(unit, g, pt, u);
    if (pt.master < 0) continue;
    if (ramp && pt.gap < 0 && theta < 1) pt.overlap0 = pt.gap / (1 - theta);
    if (close_gaps && pt.gap >= 0 && pt.gap < 1 / pair.behavior.stiffness) pt.closure = pt.gap;
    if (!pair.scheme.linear && (pt.overlap0 != 0 || pt.closure != 0))
      pair_point(unit, g, pt, u);  // existence with the offsets applied
    if (pair.scheme.linear) freeze(unit, g, pt, u);
  }
}

void ContactSystem::pair_point(const Unit& unit, const UnitGeometry& g, Point& pt, const VecX& u) const {
  const Vec3 xs = g.slave.x.transpose() * slave_weights(unit, pt);
  MasterFoot best;
  // A Gauss-Cut point first tries the master face it was cut from.
  if (pt.master >= 0 && pt.master < static_cast<int>(g.masters.size())) {
    const FaceGeometry& m = g.masters[pt.master];
    const ClosestPoint f = project_onto_face(m, xs, face_centre(m.topo));
    if (f.converged && inside_reference_face(m.topo, f.xi, kEdgeTolerance)) best = {pt.master, f};
  }
  if (best.candidate < 0) {
    std::vector<const FaceGeometry*> c;
    for (const auto& m : g.masters) c.push_back(&m);
    best = find_master(xs, c);
  }
  pt.master = best.candidate;
  pt.exists = false;
  if (best.candidate < 0) return;
  pt.xi_m = best.foot.xi;
  pt.gap = best.foot.gap;
  const Pair& pair = pairs_[unit.pair];
  if (!pair.scheme.linear) {
    // Nonlinear variants: the contact element exists when the point is within the creation
    // clearance (c0 sqrt(A)), judged at pairing and kept until the next pairing, and so is
    // its area (as ccx regenerates its node-to-face elements).
    pt.area = point_area(unit, pt, g, u);
    pt.exists = is_active(pair.law, -(pt.gap + gap_offset(pt)),
                          creation_clearance(pair.behavior, pt.area));
  }
}

void ContactSystem::freeze(const Unit& unit, const UnitGeometry& g, Point& pt, const VecX& u) const {
  const FaceGeometry& m = g.masters[pt.master];
  FaceShape s;
  face_shape(m.topo, pt.xi_m, s);
  pt.frozen.master_weights = s.N;
  pt.frozen.normal = surface_point(m, pt.xi_m).normal;
  pt.frozen.slave_weights = slave_weights(unit, pt);
  pt.frozen.area = point_area(unit, pt, g, u);
}

void ContactSystem::begin_increment(const VecX& u, const IncrementContext& ctx, int threads) {
  ctx_ = ctx;
  // Broad phase: one tree over each pair's master faces; candidates within one face size.
  std::vector<AabbTree> trees;
  std::vector<Real> margins;
  for (const Pair& pair : pairs_) {
    std::vector<Box> boxes;
    Real size = 0;
    for (const auto& f : pair.master.faces) {
      const FaceGeometry g = face_geometry(f, model_.mesh.coords, u);
      boxes.push_back(face_box(g));
      size = std::max(size, face_size(g));
    }
    for (const auto& f : pair.slave.faces) size = std::max(size, face_size(face_geometry(f, model_.mesh.coords, u)));
    trees.emplace_back(boxes);
    margins.push_back(size);
  }
  parallel_chunks(units_.size(), threads, [&](std::size_t begin, std::size_t end, int) {
    for (std::size_t k = begin; k < end; ++k) {
      find_candidates(units_[k], u, trees, margins);
      build_points(units_[k], u);
    }
  });
  // Groups: the linear variants need one per master face a point is frozen to; the others
  // one per candidate, since their points may move to any candidate during the increment.
  group_nodes_.clear();
  for (Unit& unit : units_) {
    const Pair& pair = pairs_[unit.pair];
    std::vector<char> used(unit.candidates.size(), !pair.scheme.linear);
    for (const Point& pt : unit.points)
      if (pt.master >= 0) used[pt.master] = 1;
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

std::pair<Real, Index> ContactSystem::evaluate_unit(Unit& unit, const VecX& u, bool repair) {
  const Pair& pair = pairs_[unit.pair];
  for (int gi : unit.groups) {
    if (gi < 0) continue;
    contributions_[gi].K.setZero();
    contributions_[gi].f_int.setZero();
  }
  std::pair<Real, Index> force{0, 0};
  if (unit.points.empty()) return force;
  const UnitGeometry g = geometry(unit, u);
  const PressureLaw& law = pair.law;
  PointResponse r;
  for (Point& pt : unit.points) {
    pt.active = false;
    pt.pressure = pt.energy = 0;
    if (repair) pair_point(unit, g, pt, u);
    if (pt.master < 0) continue;
    if (pair.scheme.linear) {
      pt.frozen.gap_offset = gap_offset(pt);
      frozen_point_response(g.slave.x, g.masters[pt.master].x, pt.frozen, law, 0, r);
      pt.area = pt.frozen.area;
    } else {
      if (!pt.exists) continue;
      Vec2 xi = pt.xi_m;
      if (!sliding_point_response(g.slave.x, slave_weights(unit, pt), g.masters[pt.master], xi,
                                  pt.area, gap_offset(pt), law, kNoClearanceLimit, r))
        continue;
      // Frozen pairing may let the foot slide off its face; far off, the face no longer
      // represents the surface under the point.
      if (!inside_reference_face(g.masters[pt.master].topo, xi, 0.5)) continue;
      pt.xi_m = xi;
    }
    pt.gap = r.gap;
    if (!r.active) continue;
    pt.active = true;
    pt.pressure = r.pressure.pressure;
    pt.energy = r.pressure.energy * pt.area;
    GroupContribution& c = contributions_[unit.groups[pt.master]];
    c.K += r.K;
    c.f_int += r.f_int;
    force.first += r.f_int.cwiseAbs().sum();
    force.second += r.f_int.size();
  }
  return force;
}

void ContactSystem::evaluate(const VecX& u, int evaluation, int threads) {
  std::vector<int> active(units_.size(), 0);
  std::vector<std::pair<Real, Index>> force(units_.size());
  parallel_chunks(units_.size(), threads, [&](std::size_t begin, std::size_t end, int) {
    for (std::size_t k = begin; k < end; ++k) {
      Unit& unit = units_[k];
      const Pair& pair = pairs_[unit.pair];
      const bool repair = !pair.scheme.linear && !pair.def->small_sliding && evaluation > 1 &&
                          evaluation <= kRepairEvaluations;
      force[k] = evaluate_unit(unit, u, repair);
      for (const Point& pt : unit.points) active[k] += pt.active;
    }
  });
  n_active_ = 0;
  force_abs_sum_ = 0;
  force_components_ = 0;
  for (std::size_t k = 0; k < units_.size(); ++k) {
    n_active_ += active[k];
    force_abs_sum_ += force[k].first;
    force_components_ += force[k].second;
  }
  for (const auto& c : contributions_)
    if (!c.f_int.allFinite() || !c.K.allFinite())
      throw SolverError("contact: non-finite contact force or stiffness");
}

Real ContactSystem::total_normal_force() const {
  Real total = 0;
  for (const Unit& unit : units_)
    for (const Point& pt : unit.points)
      if (pt.active) total += pt.pressure * pt.area;
  return total;
}

Real ContactSystem::max_pressure() const {
  Real p = 0;
  for (const Unit& unit : units_)
    for (const Point& pt : unit.points)
      if (pt.active) p = std::max(p, pt.pressure);
  return p;
}

Real ContactSystem::frozen_drift(const VecX& u) const {
  Real drift = 0, overclosure = 0;
  for (const Unit& unit : units_) {
    if (!pairs_[unit.pair].scheme.linear) continue;
    bool any = false;
    for (const Point& pt : unit.points) any |= pt.active;
    if (!any) continue;
    const UnitGeometry g = geometry(unit, u);
    std::vector<const FaceGeometry*> c;
    for (const auto& m : g.masters) c.push_back(&m);
    for (const Point& pt : unit.points) {
      if (!pt.active) continue;
      overclosure = std::max(overclosure, -pt.gap);
      const MasterFoot fresh = find_master(g.slave.x.transpose() * pt.frozen.slave_weights, c);
      if (fresh.candidate < 0) continue;  // slid beyond the master surface's edge
      drift = std::max(drift, std::abs(pt.gap - (fresh.foot.gap + gap_offset(pt))));
    }
  }
  return overclosure > 0 ? drift / overclosure : 0;
}

std::vector<bool> ContactSystem::nodes_outside_master(const VecX& u) const {
  std::vector<char> on_slave(model_.n_nodes(), 0), inside(model_.n_nodes(), 0);
  for (const Unit& unit : units_) {
    if (unit.node >= 0) {
      on_slave[unit.node] = 1;
      inside[unit.node] |= !unit.points.empty() && unit.points.front().master >= 0;
      continue;
    }
    const UnitGeometry g = geometry(unit, u);
    std::vector<const FaceGeometry*> c;
    for (const auto& m : g.masters) c.push_back(&m);
    const auto& nodes = pairs_[unit.pair].slave.faces[unit.face].nodes;
    for (std::size_t i = 0; i < nodes.size(); ++i) {
      on_slave[nodes[i]] = 1;
      if (!inside[nodes[i]]) inside[nodes[i]] = find_master(g.slave.x.row(i).transpose(), c).candidate >= 0;
    }
  }
  std::vector<bool> outside(model_.n_nodes(), false);
  for (int n = 0; n < model_.n_nodes(); ++n) outside[n] = on_slave[n] && !inside[n];
  return outside;
}

std::vector<output::ContactPointRecord> ContactSystem::records(const VecX& u) const {
  std::vector<output::ContactPointRecord> out;
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
      r.active = pt.active;
      r.clearance = pt.gap;
      r.pressure = pt.pressure;
      r.area = pt.area;
      r.energy = pt.energy;
      out.push_back(r);
    }
  }
  return out;
}

}  // namespace kontakt::contact
