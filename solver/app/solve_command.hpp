// `kontakt solve MODEL.inp [-o DIR] [--threads N] [--quiet]`: a job run in this process.
#pragma once

namespace kontakt::app {

/// Runs `kontakt solve` with argv[2..]; returns the exit code (1 for a usage error).
int solve_command(int argc, char** argv);

}  // namespace kontakt::app
