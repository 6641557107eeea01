#include "model/plane_expansion.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <tuple>
#include <unordered_map>
#include <unordered_set>

namespace kontakt::model {

namespace {

/// The copies of one 2D node for one kind of expansion (-1: not created).
struct Copies {
  int front = -1, middle = -1, back = -1;
  bool constrained = false;        ///< front and back tied to the node
  bool middle_constrained = false;
};

/// 2D nodes expand per (node, kind, thickness, offset): elements of different kinds or
/// sections that share a node get their own copies, each group tied to the node.
using GroupKey = std::tuple<int, Planar, Real, Real>;

std::string label_of(const Model& model, int node) {
  return std::to_string(model.mesh.node_ids[static_cast<std::size_t>(node)]);
}

const char* kind_name(Planar planar) {
  switch (planar) {
    case Planar::PlaneStress: return "plane stress";
    case Planar::PlaneStrain: return "plane strain";
    case Planar::Axisymmetric: return "axisymmetric";
    case Planar::None: break;
  }
  return "solid";
}

class Expander {
 public:
  Expander(Model& model, const std::vector<SourceLoc>& where) : model_(model), where_(where) {
    for (int label : model.mesh.node_ids) next_label_ = std::max(next_label_, label + 1);
  }

  void run() {
    check_nodes();
    for (std::size_t e = 0; e < model_.mesh.elements.size(); ++e)
      if (model_.mesh.elements[e].planar != Planar::None) expand(e);
    renumber_faces();
    adjust_step_loads();
    copy_temperatures();
    build_folds();
    expand_node_surfaces();
  }

 private:
  Model& model_;
  const std::vector<SourceLoc>& where_;
  int next_label_ = 1;
  std::map<GroupKey, Copies> groups_;
  std::vector<int> copy_source_;  ///< per new node (from n_original_): its 2D node
  int n_original_ = 0;
  std::unordered_set<int> planar_nodes_, axisymmetric_nodes_;

  [[noreturn]] void fail(std::size_t e, const std::string& message) const {
    throw InputError(where_[e], "*ELEMENT", message);
  }

  void check_nodes() {
    const Mesh& mesh = model_.mesh;
    n_original_ = model_.n_nodes();
    std::unordered_set<int> solid_nodes;
    for (const Element& el : mesh.elements)
      (el.planar == Planar::None ? solid_nodes : planar_nodes_).insert(el.nodes.begin(),
                                                                        el.nodes.end());
    for (std::size_t e = 0; e < mesh.elements.size(); ++e) {
      const Element& el = mesh.elements[e];
      if (el.planar == Planar::None) continue;
      for (int n : el.nodes) {
        if (mesh.coords(n, 2) != 0)
          fail(e, "node " + label_of(model_, n) + " of " + kind_name(el.planar) +
                      " element " + std::to_string(el.id) +
                      " is not in the z = 0 plane (ccx requires it)");
        if (solid_nodes.contains(n))
          fail(e, "node " + label_of(model_, n) + " of " + kind_name(el.planar) +
                      " element " + std::to_string(el.id) +
                      " also belongs to a solid element: connecting 2D and 3D elements is not "
                      "supported");
        if (model_.local_frames.contains(n))
          fail(e, "node " + label_of(model_, n) + " of " + kind_name(el.planar) +
                      " element " + std::to_string(el.id) +
                      " has a *TRANSFORM: not supported on nodes of 2D elements");
        if (el.planar == Planar::Axisymmetric) {
          if (mesh.coords(n, 0) < 0)
            fail(e, "node " + label_of(model_, n) + " of axisymmetric element " +
                        std::to_string(el.id) + " has a negative radius (x < 0)");
          axisymmetric_nodes_.insert(n);
        }
      }
    }
  }

  int add_node(int source, const Vec3& x) {
    Mesh& mesh = model_.mesh;
    const int index = model_.n_nodes();
    mesh.node_ids.push_back(next_label_);
    mesh.node_index.emplace(next_label_, index);
    ++next_label_;
    mesh.coords.conservativeResize(index + 1, 3);
    mesh.coords.row(index) = x.transpose();
    copy_source_.push_back(source);
    return index;
  }

  Copies& copies_of(int node, Planar planar, const SolidSection& section, Real normal,
                    bool with_middle) {
    const bool axisymmetric = planar == Planar::Axisymmetric;  // no thickness, no offset
    // In a model with axisymmetric elements everything is given for 360 degrees, so ccx
    // thins plane elements like the loads (measured: thickness / 180).
    const Real t = axisymmetric ? 0
                   : section.thickness * (axisymmetric_nodes_.empty() ? 1 : kWedgeLoadFactor);
    const Real offset = axisymmetric ? 0 : section.offset;
    Copies& c = groups_[GroupKey{node, planar, t, offset}];
    const Vec3 x = model_.mesh.coords.row(node).transpose();
    if (c.front < 0) {
      if (planar == Planar::Axisymmetric) {
        const Real r = x.x(), cs = std::cos(kWedgeHalfAngle), sn = std::sin(kWedgeHalfAngle);
        c.front = add_node(node, Vec3(r * cs, x.y(), -r * sn));
        c.back = add_node(node, Vec3(r * cs, x.y(), r * sn));
      } else {
        c.front = add_node(node, Vec3(x.x(), x.y(), -normal * t * (0.5 + offset)));
        c.back = add_node(node, Vec3(x.x(), x.y(), normal * t * (0.5 - offset)));
      }
    }
    if (with_middle && c.middle < 0) c.middle = add_node(node, Vec3(x.x(), x.y(), -normal * t * offset));
    return c;
  }

  void expand(std::size_t e) {
    Element& el = model_.mesh.elements[e];
    const int n2d = static_cast<int>(el.nodes.size());
    const int n_corner = (n2d == 3 || n2d == 6) ? 3 : 4;
    const bool quadratic = n2d > n_corner;
    // Orientation from the corners' signed area: plane elements put their front copy on the
    // side the node order faces away from (ccx's normal), so the 3D element is never inverted.
    Real area2 = 0;
    for (int a = 0; a < n_corner; ++a) {
      const int b = (a + 1) % n_corner;
      const auto xa = model_.mesh.coords.row(el.nodes[a]), xb = model_.mesh.coords.row(el.nodes[b]);
      area2 += xa(0) * xb(1) - xb(0) * xa(1);
    }
    Real extent = 0;
    for (int a = 0; a < n_corner; ++a)
      extent = std::max(extent, (model_.mesh.coords.row(el.nodes[a]) -
                                 model_.mesh.coords.row(el.nodes[0])).norm());
    if (std::abs(area2) <= 1e-12 * extent * extent)
      fail(e, std::string(kind_name(el.planar)) + " element " + std::to_string(el.id) +
                  " has zero area");
    if (el.planar == Planar::Axisymmetric && area2 < 0)
      fail(e, "axisymmetric element " + std::to_string(el.id) +
                  " is numbered clockwise in the (r, z) = (x, y) plane; ccx needs "
                  "counter-clockwise");
    const Real normal = area2 > 0 ? 1 : -1;
    const SolidSection& section = model_.sections[static_cast<std::size_t>(el.section)];

    std::vector<Copies*> copies(static_cast<std::size_t>(n2d));
    for (int a = 0; a < n2d; ++a) {
      Copies& c = copies_of(el.nodes[a], el.planar, section, normal, quadratic && a < n_corner);
      copies[static_cast<std::size_t>(a)] = &c;
    }
    std::vector<int> nodes;
    for (int a = 0; a < n_corner; ++a) nodes.push_back(copies[a]->front);
    for (int a = 0; a < n_corner; ++a) nodes.push_back(copies[a]->back);
    if (quadratic) {
      for (int a = n_corner; a < n2d; ++a) nodes.push_back(copies[a]->front);
      for (int a = n_corner; a < n2d; ++a) nodes.push_back(copies[a]->back);
      for (int a = 0; a < n_corner; ++a) nodes.push_back(copies[a]->middle);
    }
    for (int a = 0; a < n2d; ++a) constrain(e, el.nodes[a], el.planar, *copies[a]);
    el.nodes = std::move(nodes);
  }

  void equation(std::size_t e, std::vector<EquationTerm> terms) {
    model_.equations.push_back(Equation{std::move(terms), where_[e], kExpansionKeyword});
  }

  /// Ties the copies to the 2D node (once per group; a middle copy added later by a
  /// quadratic element is tied then).
  void constrain(std::size_t e, int node, Planar planar, Copies& c) {
    const bool fresh = !c.constrained;
    c.constrained = true;
    const Real cs = std::cos(kWedgeHalfAngle), sn = std::sin(kWedgeHalfAngle);
    if (fresh) {
      for (int side : {c.front, c.back}) {
        const Real sign = side == c.front ? -1 : 1;
        if (planar == Planar::Axisymmetric) {
          equation(e, {{side, 0, 1}, {node, 0, -cs}});
          equation(e, {{side, 1, 1}, {node, 1, -1}});
          equation(e, {{side, 2, 1}, {node, 0, -sign * sn}});
        } else {
          equation(e, {{side, 0, 1}, {node, 0, -1}});
          equation(e, {{side, 1, 1}, {node, 1, -1}});
          if (planar == Planar::PlaneStrain) equation(e, {{side, 2, 1}});
        }
      }
    }
    if (c.middle >= 0 && !c.middle_constrained) {
      c.middle_constrained = true;
      equation(e, {{c.middle, 0, 1}, {node, 0, -1}});
      equation(e, {{c.middle, 1, 1}, {node, 1, -1}});
      equation(e, {{c.middle, 2, 1}});
    }
    // Plane stress: the middle copy holds the mid-plane; without one (linear elements, the
    // midside nodes of quadratic ones) ccx ties front and back only at linear elements.
    if (planar == Planar::PlaneStress && fresh && c.middle < 0 && !quadratic_of(e))
      equation(e, {{c.front, 2, 1}, {c.back, 2, 1}});
  }

  bool quadratic_of(std::size_t e) const {
    const Element& el = model_.mesh.elements[e];
    return el.type == element::ElementType::C3D20 || el.type == element::ElementType::C3D20R ||
           el.type == element::ElementType::C3D15;
  }

  void renumber_faces() {
    const auto& elements = model_.mesh.elements;
    const auto planar = [&](int element) {
      return elements[static_cast<std::size_t>(element)].planar != Planar::None;
    };
    for (auto& [name, surface] : model_.surfaces)
      for (ElementFace& f : surface.faces)
        if (planar(f.element)) f.face += 2;
    for (Step& step : model_.steps)
      for (PressureLoad& p : step.pressures)
        if (planar(p.face.element)) p.face.face += 2;
  }

  void adjust_step_loads() {
    for (Step& step : model_.steps) {
      // ccx ignores out-of-plane loads and supports of 2D nodes: the expansion decides z.
      std::erase_if(step.cloads, [&](const ConcentratedLoad& l) {
        return l.dof == 2 && planar_nodes_.contains(l.node);
      });
      std::erase_if(step.boundaries, [&](const Boundary& b) {
        return b.dof == 2 && planar_nodes_.contains(b.node);
      });
      // A model with axisymmetric elements is given for 360 degrees: every load (measured on
      // the plane stress nodes of such a model too).
      if (!axisymmetric_nodes_.empty())
        for (ConcentratedLoad& l : step.cloads) l.value *= kWedgeLoadFactor;
    }
  }

  VecX extended(const VecX& values) const {
    if (values.size() == 0) return values;
    VecX out(model_.n_nodes());
    out.head(values.size()) = values;
    for (std::size_t k = 0; k < copy_source_.size(); ++k)
      out[n_original_ + static_cast<Index>(k)] = values[copy_source_[k]];
    return out;
  }

  void copy_temperatures() {
    model_.initial_temperatures = extended(model_.initial_temperatures);
    for (Step& step : model_.steps) step.temperatures = extended(step.temperatures);
  }

  /// ccx averages a node's value over its groups (a node shared by plane and axisymmetric
  /// elements) and sums the forces of all its copies.
  void build_folds() {
    std::map<int, std::vector<const Copies*>> of_node;
    for (const auto& [key, c] : groups_) of_node[std::get<0>(key)].push_back(&c);
    for (const auto& [node, groups] : of_node) {
      PlanarFold fold{node, {}, {}};
      const Real share = 1.0 / static_cast<Real>(groups.size());
      for (const Copies* c : groups) {
        const bool middle = c->middle >= 0;
        const Real side = middle ? 1.0 / 6 : 0.5;
        fold.expanded.push_back(c->front);
        fold.weights.push_back(share * side);
        if (middle) {
          fold.expanded.push_back(c->middle);
          fold.weights.push_back(share * 4.0 / 6);
        }
        fold.expanded.push_back(c->back);
        fold.weights.push_back(share * side);
      }
      model_.planar_folds.push_back(std::move(fold));
    }
  }

  /// A node surface's 2D node stands for all its copies, each a slave node with its share of
  /// the expanded faces (bolt: node-to-surface contact on CAX8 nodes).
  void expand_node_surfaces() {
    std::unordered_map<int, const PlanarFold*> fold_of;
    for (const PlanarFold& fold : model_.planar_folds) fold_of[fold.node] = &fold;
    for (auto& [name, surface] : model_.surfaces) {
      std::vector<int> nodes;
      for (int n : surface.nodes) {
        const auto fold = fold_of.find(n);
        if (fold == fold_of.end())
          nodes.push_back(n);
        else
          nodes.insert(nodes.end(), fold->second->expanded.begin(), fold->second->expanded.end());
      }
      std::sort(nodes.begin(), nodes.end());
      nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
      surface.nodes = std::move(nodes);
    }
  }
};

}  // namespace

void expand_planar_elements(Model& model, const std::vector<SourceLoc>& element_where) {
  const bool any = std::any_of(model.mesh.elements.begin(), model.mesh.elements.end(),
                               [](const Element& el) { return el.planar != Planar::None; });
  if (any) Expander(model, element_where).run();
}

void fold_to_planar_nodes(const std::vector<PlanarFold>& folds, MatX3& U, MatX3& RF) {
  for (const PlanarFold& fold : folds) {
    U.row(fold.node).setZero();
    RF.row(fold.node).setZero();
    for (std::size_t k = 0; k < fold.expanded.size(); ++k) {
      U.row(fold.node) += fold.weights[k] * U.row(fold.expanded[k]);
      RF.row(fold.node) += RF.row(fold.expanded[k]);
    }
  }
}

}  // namespace kontakt::model
