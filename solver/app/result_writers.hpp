// The result files of one `kontakt solve` run, fed by the analysis frame by frame.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "analysis/linear_static.hpp"
#include "output/dat_writer.hpp"
#include "output/frd_writer.hpp"
#include "output/hdf5_writer.hpp"

namespace kontakt::app {

/// Writes each frame to the .dat, HDF5 and (when the deck has file requests) .frd files, and
/// records every attempted increment (from the increment and cutback events) for the HDF5
/// /history table.
class ResultWriters final : public analysis::FrameSink, public analysis::EventSink {
 public:
  /// Opens DIR/JOB.dat, DIR/JOB.hdf.partial and, for a deck with file requests, DIR/JOB.frd.
  ResultWriters(const model::Model& model, const std::filesystem::path& dir,
                const std::string& job);
  void on_frame(const model::Step& step, const output::Frame& frame) override;
  void on_event(const analysis::Event& event) override;
  /// Completes the HDF5 file (rename from .partial) and writes the XDMF sidecar.
  void finish();

 private:
  output::DatWriter dat_;
  output::Hdf5Writer hdf5_;
  std::optional<output::FrdWriter> frd_;
};

}  // namespace kontakt::app
