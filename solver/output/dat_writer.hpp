// The .dat file in CalculiX 2.20's exact layout: *NODE PRINT / *EL PRINT / *CONTACT PRINT
// blocks.
#pragma once

#include <filesystem>
#include <fstream>
#include <string>
#include <unordered_map>

#include "model/model.hpp"
#include "output/frame.hpp"

namespace kontakt::output {

/// True when print request `request` is due at `frame`: every `frequency`-th increment of the
/// step and always at the step's last increment; never when frequency <= 0. A step whose output
/// follows *TIME POINTS (Frame::at_time_point engaged) prints at those and at its end only.
/// ccx note: ccx applies ONE print frequency to all requests, the last FREQUENCY= given, carried
/// into later steps; the deck reader is expected to store that effective value in each request.
bool print_due(const model::PrintRequest& request, const Frame& frame);
/// The same rule for a *CONTACT PRINT request.
bool print_due(const model::ContactRequest& request, const Frame& frame);

class DatWriter {
 public:
  /// Creates (truncates) the file at `path`.
  DatWriter(const model::Model& model, std::filesystem::path path);

  /// Appends the blocks of every print request of `step` that is due at `frame`, in request
  /// order (contact prints where ContactRequest::after_prints puts them) and, within a
  /// request, in the order its variables were given. Unknown variables are skipped. Throws
  /// SolverError when a set is missing or the frame is too small.
  ///
  /// Contact prints list the active points of Frame::contact_points, as ccx lists its contact
  /// elements: by pair, then by slave node label (node-to-surface) or by slave element label
  /// and face (surface-to-surface; a face's points keep their order). Headers say "slave node"
  /// or "slave element+face" by the type of the deck's pairs (ccx allows only one type per
  /// deck); a deck without pairs prints no contact blocks.
  void write(const model::Step& step, const Frame& frame);

  const std::filesystem::path& path() const { return path_; }

 private:
  void node_request(const model::PrintRequest& r, const Frame& f);
  void element_request(const model::PrintRequest& r, const Frame& f);
  void contact_request(const model::ContactRequest& r, const Frame& f);
  void header(std::string_view prefix, const std::string& set, const Frame& f);

  const model::Model& model_;
  std::filesystem::path path_;
  std::ofstream out_;
  int largest_node_label_ = 0, largest_element_label_ = 0;  ///< where print orders stop (ccx)
  /// T3D2 truss label -> Model::connectors index: *EL PRINT lists a truss's rows (Frame::
  /// truss_S, ...) where its set has it, as ccx does its expanded element.
  std::unordered_map<int, int> truss_index_;
  /// Internal node -> the 2D node it is an expanded copy of (model::PlanarFold), or itself:
  /// contact prints name the 2D node, once, as ccx does.
  std::vector<int> printed_node_;
};

}  // namespace kontakt::output
