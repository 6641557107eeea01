// The other side of worker_protocol.hpp: what runs inside a worker process
// (`kontaktd job-worker check|run ...`). It ties itself to the daemon (killed when the daemon
// dies), takes the resource limits, then checks the deck or runs the job through app::run_job,
// writing its report to descriptor 3 and ending with a worker::Exit code.
#pragma once

#include <string>
#include <vector>

namespace kontakt::server {

/// argv after worker::kCommand (`standby PARENT_PID`, or the work's arguments); returns the
/// process's exit code.
int job_worker_main(std::vector<std::string> argv);

}  // namespace kontakt::server
