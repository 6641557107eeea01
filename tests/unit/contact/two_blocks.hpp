// Two stacked blocks for the contact tests, generated as deck text: a lower block
// [0,1]^2 x [0,1] and an upper block of edge `upper_size` on top of it (rotated about z and
// shifted in-plane), each meshed with its own element type and density, so the interface meshes
// do not match. Surfaces: SLAVE (bottom of the upper block), MASTER (top of the lower block),
// LOADED (top of the upper block, for *DLOAD P-faces); node sets BOTTOM and TOP.
#pragma once

#include <Eigen/Geometry>
#include <cmath>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "inp/read_deck.hpp"
#include "model/model.hpp"

namespace kontakt::contact::fixtures {

struct BlockSpec {
  std::string type = "C3D8";  ///< C3D8, C3D8R, C3D20, C3D20R, C3D6, C3D15
  int n_xy = 2, n_z = 1;
};

struct TwoBlocks {
  BlockSpec lower, upper;
  Real upper_size = 1;
  Real rotation_deg = 0;       ///< of the upper block about the vertical axis through its centre
  Real offset_x = 0, offset_y = 0;
  Real gap = 0;                ///< initial clearance (negative: overlap)
  Real young = 1000, poisson = 0;
  Real pressure = 1;           ///< on the top of the upper block
};

namespace detail {

struct Mesher {
  std::ostringstream nodes, elements;
  std::map<std::string, std::vector<int>> elsets, nsets;
  int next_element = 1;

  /// Meshes one block; `place` maps unit-cube coordinates to space. Node labels start at
  /// `base`; elements of the first / last z layer go to elsets `first_layer` / `last_layer`.
  template <class Place>
  void block(const BlockSpec& s, int base, Place place, const std::string& elset,
             const std::string& first_layer, const std::string& last_layer,
             const std::string& bottom_nset, const std::string& top_nset) {
    const int gx = 2 * s.n_xy + 1, gz = 2 * s.n_z + 1;
    std::map<int, bool> used;
    auto id = [&](int i, int j, int k) { return base + i + gx * (j + gx * k); };
    auto node = [&](int i, int j, int k) {
      const int n = id(i, j, k);
      if (!used[n]) {
        used[n] = true;
        const Eigen::Vector3d x = place(Eigen::Vector3d(Real(i) / (gx - 1), Real(j) / (gx - 1), Real(k) / (gz - 1)));
        nodes << n << ", " << x(0) << ", " << x(1) << ", " << x(2) << "\n";
        if (k == 0) nsets[bottom_nset].push_back(n);
        if (k == gz - 1) nsets[top_nset].push_back(n);
      }
      return n;
    };
    const bool quadratic = s.type == "C3D20" || s.type == "C3D20R" || s.type == "C3D15";
    const bool wedge = s.type == "C3D6" || s.type == "C3D15";
    elements.precision(17);
    elements << "*ELEMENT, TYPE=" << s.type << ", ELSET=" << elset << "\n";
    for (int k = 0; k < s.n_z; ++k)
      for (int j = 0; j < s.n_xy; ++j)
        for (int i = 0; i < s.n_xy; ++i) {
          // Corner indices on the half-step grid, ccx hex order.
          const int c[8][3] = {{2 * i, 2 * j, 2 * k},         {2 * i + 2, 2 * j, 2 * k},
                               {2 * i + 2, 2 * j + 2, 2 * k}, {2 * i, 2 * j + 2, 2 * k},
                               {2 * i, 2 * j, 2 * k + 2},     {2 * i + 2, 2 * j, 2 * k + 2},
                               {2 * i + 2, 2 * j + 2, 2 * k + 2}, {2 * i, 2 * j + 2, 2 * k + 2}};
          auto corner = [&](int a) { return node(c[a][0], c[a][1], c[a][2]); };
          auto mid = [&](int a, int b) {
            return node((c[a][0] + c[b][0]) / 2, (c[a][1] + c[b][1]) / 2, (c[a][2] + c[b][2]) / 2);
          };
          std::vector<std::vector<int>> cells;
          if (!wedge) {
            std::vector<int> e;
            for (int a = 0; a < 8; ++a) e.push_back(corner(a));
            if (quadratic) {
              for (auto [a, b] : {std::pair{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6}, {6, 7},
                                  {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}})
                e.push_back(mid(a, b));
            }
            cells.push_back(e);
          } else {
            for (auto tri : {std::array<int, 3>{0, 1, 2}, std::array<int, 3>{0, 2, 3}}) {
              std::vector<int> e;
              for (int a : tri) e.push_back(corner(a));
              for (int a : tri) e.push_back(corner(a + 4));
              if (quadratic) {
                for (int t = 0; t < 3; ++t) e.push_back(mid(tri[t], tri[(t + 1) % 3]));
                for (int t = 0; t < 3; ++t) e.push_back(mid(tri[t] + 4, tri[(t + 1) % 3] + 4));
                for (int t = 0; t < 3; ++t) e.push_back(mid(tri[t], tri[t] + 4));
              }
              cells.push_back(e);
            }
          }
          for (const auto& e : cells) {
            const int label = next_element++;
            elements << label;
            for (std::size_t a = 0; a < e.size(); ++a) elements << (a % 15 == 14 ? ",\n" : ", ") << e[a];
            elements << "\n";
            if (k == 0) elsets[first_layer].push_back(label);
            if (k == s.n_z - 1) elsets[last_layer].push_back(label);
          }
        }
  }
};

inline void write_set(std::ostringstream& out, const std::string& kind, const std::string& name,
                      const std::vector<int>& members) {
  out << "*" << kind << ", " << kind << "=" << name << "\n";
  for (std::size_t i = 0; i < members.size(); ++i)
    out << members[i] << ((i % 10 == 9 || i + 1 == members.size()) ? "\n" : ", ");
}

}  // namespace detail

/// The deck text, without contact cards (the tests add the pair to the model).
inline std::string two_blocks_deck(const TwoBlocks& t) {
  detail::Mesher m;
  m.nodes.precision(17);
  m.block(t.lower, 1, [](const Eigen::Vector3d& p) { return p; }, "LOWER", "LOWER_BOTTOM",
          "LOWER_TOP", "BOTTOM", "LOWER_TOPN");
  const Real angle = t.rotation_deg * M_PI / 180;
  const Eigen::Matrix3d R = Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  m.block(t.upper, 100000, [&](const Eigen::Vector3d& p) {
    Eigen::Vector3d q = t.upper_size * (p - Eigen::Vector3d(0.5, 0.5, 0));
    q = R * q;
    return Eigen::Vector3d(q(0) + 0.5 + t.offset_x, q(1) + 0.5 + t.offset_y, q(2) + 1 + t.gap);
  }, "UPPER", "UPPER_BOTTOM", "UPPER_TOP", "UPPER_BOTTOMN", "TOP");
  std::ostringstream d;
  d << "*NODE\n" << m.nodes.str() << m.elements.str();
  for (const auto& [name, members] : m.elsets) detail::write_set(d, "ELSET", name, members);
  for (const auto& [name, members] : m.nsets) detail::write_set(d, "NSET", name, members);
  // Bottom of an element: hex S1, wedge S1; top: hex S2, wedge S2.
  d << "*SURFACE, NAME=SLAVE\nUPPER_BOTTOM, S1\n";
  d << "*SURFACE, NAME=MASTER\nLOWER_TOP, S2\n";
  d << "*MATERIAL, NAME=M\n*ELASTIC\n" << t.young << ", " << t.poisson << "\n";
  d << "*SOLID SECTION, ELSET=LOWER, MATERIAL=M\n*SOLID SECTION, ELSET=UPPER, MATERIAL=M\n";
  d << "*STEP\n*STATIC\n1., 1.\n*BOUNDARY\nBOTTOM, 1, 3\nTOP, 1, 2\n";
  d << "*DLOAD\nUPPER_TOP, P2, " << t.pressure << "\n";
  d << "*EL PRINT, ELSET=UPPER\nS\n*EL PRINT, ELSET=LOWER\nS\n*END STEP\n";
  return d.str();
}

/// Reads the deck and adds one LINEAR surface interaction (K) and the pair SLAVE-MASTER.
inline model::Model two_blocks_model(const TwoBlocks& t, Real stiffness,
                                     const model::ContactScheme& scheme) {
  model::Model m = inp::read_deck_text(two_blocks_deck(t), "two_blocks.inp");
  model::SurfaceInteraction si;
  si.name = "SI";
  si.behavior.stiffness = stiffness;
  si.behavior.tension_limit = t.young / 70000;
  m.interactions.push_back(si);
  model::ContactPair cp;
  cp.type = scheme.kind == model::ContactScheme::Kind::NodeToSurface
                ? model::ContactPair::Type::NodeToSurface
                : model::ContactPair::Type::SurfaceToSurface;
  cp.interaction = 0;
  cp.slave = "SLAVE";
  cp.master = "MASTER";
  cp.scheme = scheme;
  m.contact_pairs.push_back(cp);
  return m;
}

}  // namespace kontakt::contact::fixtures
