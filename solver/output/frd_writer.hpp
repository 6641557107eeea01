// The ASCII .frd results file in CalculiX 2.20's layout (what cgx opens): header, nodes,
// elements, then one result block per requested field and output frame.
// Layout: ../../shared/reference/ccx-behaviour.md §4.3 and solver/output/README.md.
//
// Crash consistency: between frames the file is complete (it always ends with ` 9999`); the
// next frame overwrites that end line. A job killed at any moment leaves a file cgx reads up
// to the last whole frame, or one cut inside a frame's block (the write in progress).
#pragma once

#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <vector>

#include "element/element_type.hpp"
#include "model/model.hpp"
#include "output/frame.hpp"

namespace kontakt::output {

/// File-request variables the .frd writer writes (names as in *NODE FILE / *EL FILE /
/// *CONTACT FILE; CDIS and CSTR both stand for the CONTACT block, as in ccx). Others (ME,
/// ENER, CELS, ...) are not written.
inline const std::set<std::string> kFrdFields{"U", "NT", "S", "E", "RF", "PEEQ", "CDIS", "CSTR"};

/// The .frd fields `step` requests: its file requests' variables that are in kFrdFields.
std::set<std::string> frd_fields(const model::Step& step);
/// True when any step of the model has a file request (then the job writes MODEL.frd).
bool wants_frd(const model::Model& model);

/// A value as ccx writes it: single precision, %12.5E.
std::string frd_value(double v);
/// The 12-column time field of the 100CL line: fixed point with as many decimals as fit for
/// 1 <= t < 1e10, %12.5E otherwise (0 < t < 1 included).
std::string frd_time(double t);
/// One node's data lines of a result block: ` -1` + node (I10) + up to 6 values, then
/// ` -2` + 10 blanks + up to 6 values for the rest; each line ends with a newline.
std::string frd_result_lines(int node, const double* values, int count);
/// frd element type: 1 he8, 2 pe6, 3 te4, 4 he20, 5 pe15, 6 te10.
int frd_element_type(element::ElementType type);
/// The element's local node indices (0-based, ccx order) in the order the frd lists them:
/// C3D20(R) nodes 1-12, 17-20, 13-16; C3D15 nodes 1-9, 13-15, 10-12; the others as given.
std::vector<int> frd_node_order(element::ElementType type);

class FrdWriter {
 public:
  /// Creates (truncates) `path` and writes the header, the nodes used by elements (by label)
  /// and the elements, then the end line. Throws SolverError when the file cannot be written.
  FrdWriter(const model::Model& model, std::filesystem::path path);

  /// Appends the result blocks `step` requests when its file output is due at `frame` (every
  /// frequency-th increment and at the step's end; file_output_due), in ccx's block order:
  /// DISP, NDTEMP, STRESS, TOSTRAIN, FORC, PE, CONTACT. A step without .frd fields writes
  /// nothing. Throws SolverError when the file cannot be written.
  void write(const model::Step& step, const Frame& frame);

  const std::filesystem::path& path() const { return path_; }
  int frames_written() const { return frames_; }

  /// A declared component (` -5` line): name, type (1 scalar, 2 vector, 4 tensor), indices.
  struct Component {
    std::string name;
    int type, i, j;
  };

 private:
  /// One block: 1PSTEP, 100CL, -4 and -5 lines, then `values` (one row per model node, the
  /// stored components as columns) of the written nodes, 6 values a line.
  void block(const Frame& frame, const std::string& name,
             const std::vector<Component>& components, const MatX& values);
  /// Writes the end line after the current position and flushes; remembers where it starts.
  void end_file();

  const model::Model& model_;
  std::filesystem::path path_;
  std::ofstream out_;
  std::vector<int> nodes_;           ///< internal indices of the written nodes, by label
  std::streampos end_line_at_ = 0;   ///< where ` 9999` starts
  int blocks_ = 0;                   ///< 1PSTEP counter over the file
  int frames_ = 0;                   ///< result sets (the 100CL counter)
};

}  // namespace kontakt::output
