// HDF5 results file (kontakt-results 1.0, with a VTKHDF 1.0 view ParaView opens directly) and
// its XDMF 3 sidecar. Layout: proto/results_layout.md.
//
// Crash consistency: between writes the file is complete and flushed (mesh, every frame so far,
// their history, the VTKHDF view of the newest frame) and named MODEL.hdf, with MODEL.xdmf
// beside it. While the writer changes it, both are named *.partial. So a process killed at any
// moment leaves either a whole MODEL.hdf with its sidecar or *.partial files a write was cut
// short in (which nobody should read); kontaktd publishes only the former.
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "model/model.hpp"
#include "output/frame.hpp"

namespace kontakt::output {

/// Output fields the HDF5 writer understands (names as in *NODE FILE / *EL FILE / *CONTACT
/// FILE; CDIS and CSTR both stand for all nodal contact arrays, as they do in ccx).
inline const std::set<std::string> kHdf5Fields{"U",    "RF",   "S",    "E",   "ENER",
                                               "PEEQ", "EVOL", "CDIS", "CSTR", "CELS"};

/// The union over all steps of the *NODE FILE / *EL FILE / *NODE OUTPUT / *ELEMENT OUTPUT /
/// *CONTACT FILE / *CONTACT OUTPUT variables we can write (others are dropped). When no step
/// requests anything the default is {"U", "S"}, plus {"CDIS", "CSTR", "CELS"} for a model with
/// contact pairs (a results file without fields is useless in ParaView).
std::set<std::string> requested_fields(const model::Model& model);

/// Every variable of the *NODE FILE / *EL FILE / *CONTACT FILE requests of `step` (and their
/// OUTPUT synonyms), known to a writer or not.
std::set<std::string> file_variables(const model::Step& step);

/// True when any file request of `step` is due at `frame` (every frequency-th increment and at
/// step end; at the time points and the step end when the step's output follows *TIME POINTS).
/// A step without file requests is due at every step end only.
bool file_output_due(const model::Step& step, const Frame& frame);

/// Initialises the HDF5 library and its deflate filter with a small file in memory: a process
/// that waits for its job (kontaktd's standby worker) pays for them before the job, not in it.
void warm_up_hdf5();

class Hdf5Writer {
 public:
  /// Creates DIR/MODEL.hdf with /mesh, the /VTKHDF geometry, an empty history and no frames
  /// yet. `fields` as returned by requested_fields(). Throws SolverError on HDF5 failures.
  Hdf5Writer(const model::Model& model, std::filesystem::path dir, std::string model_name,
             std::set<std::string> fields);
  ~Hdf5Writer();  ///< closes; without finish() the file holds the frames written so far
  Hdf5Writer(const Hdf5Writer&) = delete;
  Hdf5Writer& operator=(const Hdf5Writer&) = delete;

  /// Appends /frames/NNNNNN (numbered from 000001 in call order) and points the VTKHDF view
  /// (PointData/CellData hard links) at it. A model with contact pairs also gets the nodal
  /// contact arrays (CDIS or CSTR requested) and the contact point table (any contact field
  /// requested).
  void write(const Frame& frame);
  /// Records one attempted increment for /history/increments (written with the next frame or
  /// by finish()).
  void add_increment(const IncrementRecord& record);
  /// Writes the remaining history and closes the file.
  void finish();

  std::filesystem::path partial_path() const;
  std::filesystem::path final_path() const;
  std::filesystem::path xdmf_path() const;
  int frames_written() const { return static_cast<int>(frames_.size()); }

 private:
  struct FrameInfo {
    std::string group;       ///< "000001"
    double time;
    std::vector<std::string> node_arrays;  ///< names of nodal arrays in the frame group
    std::vector<std::string> cell_arrays;
  };
  struct Impl;

  void write_mesh();
  void write_xdmf() const;
  void create_history(std::int64_t group);  // an hid_t
  void append_history();
  void link_view_to(const FrameInfo& frame);
  /// MODEL.hdf -> MODEL.hdf.partial (and the sidecar) before the file changes.
  void begin_update();
  /// Flushes and renames back (MODEL.hdf), then rewrites MODEL.xdmf.
  void publish();

  const model::Model& model_;
  std::filesystem::path dir_;
  std::string name_;
  std::set<std::string> fields_;
  std::unique_ptr<Impl> impl_;
  std::vector<FrameInfo> frames_;
  std::vector<IncrementRecord> history_;
  bool ip_offset_written_ = false;
  bool finished_ = false;
};

}  // namespace kontakt::output
