// The .dat file in CalculiX 2.20's exact layout: *NODE PRINT / *EL PRINT blocks.
#pragma once

#include <filesystem>
#include <fstream>
#include <string>

#include "model/model.hpp"
#include "output/frame.hpp"

namespace kontakt::output {

/// True when print request `request` is due at `frame`: every `frequency`-th increment of the
/// step and always at the step's last increment; never when frequency <= 0.
/// ccx note: ccx applies ONE print frequency to all requests, the last FREQUENCY= given, carried
/// into later steps; the deck reader is expected to store that effective value in each request.
bool print_due(const model::PrintRequest& request, const Frame& frame);

class DatWriter {
 public:
  /// Creates (truncates) the file at `path`.
  DatWriter(const model::Model& model, std::filesystem::path path);

  /// Appends the blocks of every print request of `step` that is due at `frame`, in request
  /// order and, within a request, in the order its variables were given. Unknown variables
  /// are skipped. Throws SolverError when a set is missing or the frame is too small.
  void write(const model::Step& step, const Frame& frame);

  const std::filesystem::path& path() const { return path_; }

 private:
  void node_request(const model::PrintRequest& r, const Frame& f);
  void element_request(const model::PrintRequest& r, const Frame& f);
  void header(std::string_view prefix, const std::string& set, const Frame& f);

  const model::Model& model_;
  std::filesystem::path path_;
  std::ofstream out_;
};

}  // namespace kontakt::output
