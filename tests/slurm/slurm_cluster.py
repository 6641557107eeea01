"""A private single-host Slurm for tests (ecosystem.md section 4.3): munged, slurmctld and
slurmd started from Debian's packages with their own key, socket, ports, slurm.conf, spool and
logs under one temporary folder, and torn down by their pid files, also when a test fails.

As a module: `with LocalSlurm() as slurm: ... slurm.env` (SLURM_CONF for the clients).
By hand: `slurm_cluster.py start DIR` prints the SLURM_CONF to export; `slurm_cluster.py stop
DIR` stops it. Needs root (slurmd runs jobs as their submitter; munged runs with --force).
"""
import os
import shutil
import signal
import socket
import subprocess
import sys
import tempfile
import time

START_TIMEOUT = 30.0


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def slurm_conf(d, ctld_port, slurmd_port, cpus, memory_mb):
    return f"""# private test cluster written by tests/slurm/slurm_cluster.py
ClusterName=kontakttest
SlurmctldHost=localhost
SlurmUser=root
SlurmdUser=root
SlurmctldPort={ctld_port}
SlurmdPort={slurmd_port}
AuthType=auth/munge
AuthInfo=socket={d}/munge.socket
CredType=cred/munge
StateSaveLocation={d}/state
SlurmdSpoolDir={d}/spool
SlurmctldPidFile={d}/slurmctld.pid
SlurmdPidFile={d}/slurmd.pid
SlurmctldLogFile={d}/slurmctld.log
SlurmdLogFile={d}/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core_Memory
DefMemPerCPU=500
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/filetxt
JobCompLoc={d}/jobcomp.txt
MinJobAge=300
ReturnToService=2
SchedulerParameters=sched_interval=1
KillWait=5
MpiDefault=none
NodeName=localhost CPUs={cpus} RealMemory={memory_mb} State=UNKNOWN
PartitionName=debug Nodes=localhost Default=YES MaxTime=INFINITE State=UP
"""


class LocalSlurm:
    """A running private cluster; `env` holds SLURM_CONF for sbatch, squeue, scancel."""

    def __init__(self, folder=None, cpus=2, memory_mb=2000):
        self.own = folder is None
        self.dir = folder or tempfile.mkdtemp(prefix="kontakt-slurm-")
        self.cpus, self.memory_mb = cpus, memory_mb
        self.conf = os.path.join(self.dir, "slurm.conf")
        self.env = dict(os.environ, SLURM_CONF=self.conf)

    def __enter__(self):
        try:
            self.start()
        except BaseException:
            self.stop()
            raise
        return self

    def __exit__(self, *exc):
        self.stop()

    def _run(self, argv, **kw):
        return subprocess.run(argv, env=self.env, check=True, capture_output=True, text=True, **kw)

    def start(self):
        if os.geteuid() != 0:
            raise RuntimeError("the test Slurm needs root (slurmd starts jobs as their user)")
        d = self.dir
        for sub in ("state", "spool"):
            os.makedirs(os.path.join(d, sub), exist_ok=True)
        os.chmod(d, 0o755)  # jobs and clients read slurm.conf
        self._run(["mungekey", "--create", "--keyfile", f"{d}/munge.key"])
        self._run(["munged", "--force", f"--socket={d}/munge.socket", f"--key-file={d}/munge.key",
                   f"--pid-file={d}/munged.pid", f"--log-file={d}/munged.log",
                   f"--seed-file={d}/munged.seed"])
        with open(self.conf, "w") as f:
            f.write(slurm_conf(d, free_port(), free_port(), self.cpus, self.memory_mb))
        self._run(["slurmctld", "-f", self.conf])
        self._run(["slurmd", "-f", self.conf])
        deadline = time.monotonic() + START_TIMEOUT
        while time.monotonic() < deadline:
            out = subprocess.run(["sinfo", "-h", "-o", "%t"], env=self.env, capture_output=True,
                                 text=True)
            if out.returncode == 0 and out.stdout.strip() == "idle":
                return self
            time.sleep(0.2)
        raise RuntimeError("the test Slurm's node did not become idle; slurmctld log:\n" +
                           self.log("slurmctld.log") + "\nslurmd log:\n" + self.log("slurmd.log"))

    def log(self, name):
        try:
            with open(os.path.join(self.dir, name)) as f:
                return f.read()[-4000:]
        except OSError:
            return "(none)"

    def stop(self):
        """Every daemon by its pid file (slurmd first: it ends its jobs), then the folder."""
        for name in ("slurmd", "slurmctld", "munged"):
            path = os.path.join(self.dir, name + ".pid")
            try:
                with open(path) as f:
                    pid = int(f.read().strip())
                os.kill(pid, signal.SIGTERM)
            except (OSError, ValueError):
                continue
            deadline = time.monotonic() + 10
            while time.monotonic() < deadline and os.path.exists(f"/proc/{pid}"):
                time.sleep(0.05)
            if os.path.exists(f"/proc/{pid}"):
                os.kill(pid, signal.SIGKILL)
        if self.own:
            shutil.rmtree(self.dir, ignore_errors=True)


def main(argv):
    if len(argv) != 3 or argv[1] not in ("start", "stop"):
        sys.exit("usage: slurm_cluster.py start|stop DIR")
    cluster = LocalSlurm(os.path.abspath(argv[2]))
    if argv[1] == "start":
        with_cleanup = cluster.__enter__()
        print(f"export SLURM_CONF={with_cleanup.conf}")
    else:
        cluster.stop()


if __name__ == "__main__":
    main(sys.argv)
