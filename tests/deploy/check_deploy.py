#!/usr/bin/python3
"""Checks the deployment files as far as a machine without systemd running and without a
container engine allows (issue 14):

- deploy/kontaktd.service: `systemd-analyze verify` (syntax, directives, the ExecStart
  program: the installed kontaktd of this build) with no complaint, and `systemd-analyze
  security --offline=yes` rating its exposure OK (at most MAX_EXPOSURE); every KONTAKTD_*
  variable it sets is one kontaktd knows; the installed kontaktd started with exactly the
  unit's environment (port and data folder made temporary) answers /healthz and drains on
  SIGTERM with exit code 0.
- deploy/Containerfile: it builds with the project's own scripts (deploy/install-deps.sh,
  deploy/build.sh) and installs with `cmake --install`; its CMD is the installed kontaktd;
  its ENV variables are ones kontaktd knows; the installed kontaktd started with that
  environment answers /healthz.
- `cmake --install` lays out what both use: bin/kontaktd, bin/kontakt, the unit under
  lib/systemd/system, the README under share/doc/kontakt.

  check_deploy.py --build BUILD_DIR
"""
import argparse
import os
import re
import subprocess
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.join(REPO, "tests", "server"))
import kontaktd_harness as harness  # noqa: E402

UNIT = os.path.join(REPO, "deploy", "kontaktd.service")
CONTAINERFILE = os.path.join(REPO, "deploy", "Containerfile")
INSTALLED_KONTAKTD = "/usr/local/bin/kontaktd"
MAX_EXPOSURE = 2.0  # systemd's scale: 0 (locked down) ... 10 (exposed); "OK" is below 3.5
BUILD = None


def unit_environment(text):
    return dict(re.findall(r"^Environment=(KONTAKTD_\w+)=(\S*)$", text, re.M))


def container_environment(text):
    env = {}
    for block in re.findall(r"^ENV\s+((?:.*\\\n)*.*)$", text, re.M):
        env.update(re.findall(r"(KONTAKTD_\w+)=(\S+)", block))
    return env


def known_variables(kontaktd):
    text = subprocess.run([kontaktd, "--help"], capture_output=True, text=True).stdout
    return set(re.findall(r"\[(KONTAKTD_\w+)\]", text))


class Installed:
    """`cmake --install` of the build into a temporary prefix."""

    def __enter__(self):
        self.dir = tempfile.TemporaryDirectory(prefix="kontakt-install-")
        subprocess.run(["cmake", "--install", BUILD, "--prefix", self.dir.name], check=True,
                       stdout=subprocess.DEVNULL)
        return self.dir.name

    def __exit__(self, *exc):
        self.dir.cleanup()


def serves_with(test, kontaktd, env):
    """The daemon started with `env` (port and data folder: the harness's) answers /healthz and
    drains on SIGTERM."""
    env = {k: v for k, v in env.items() if k not in ("KONTAKTD_PORT", "KONTAKTD_DATA_DIR")}
    env["KONTAKTD_BIND"] = "127.0.0.1"  # the test listens on loopback only
    d = harness.Daemon(kontaktd, env=env).start()
    try:
        status, _, body = d.json("GET", "/healthz")
        test.assertEqual(status, 200, body)
    finally:
        test.assertEqual(d.terminate(timeout=30), 0)


class InstallTest(unittest.TestCase):
    def test_install_lays_out_programs_unit_and_docs(self):
        with Installed() as prefix:
            for path in ("bin/kontaktd", "bin/kontakt", "lib/systemd/system/kontaktd.service",
                         "share/doc/kontakt/README.md"):
                self.assertTrue(os.path.exists(os.path.join(prefix, path)), path)
            self.assertTrue(os.access(os.path.join(prefix, "bin/kontaktd"), os.X_OK))


class UnitTest(unittest.TestCase):
    def setUp(self):
        with open(UNIT) as f:
            self.text = f.read()

    def test_unit_starts_the_installed_daemon(self):
        self.assertRegex(self.text, rf"(?m)^ExecStart={re.escape(INSTALLED_KONTAKTD)}$")

    def test_systemd_verifies_it_and_rates_its_exposure_ok(self):
        with Installed() as prefix, tempfile.TemporaryDirectory() as tmp:
            # The same unit, with ExecStart pointing at this build's installed program.
            unit = os.path.join(tmp, "kontaktd.service")
            with open(unit, "w") as f:
                f.write(self.text.replace(INSTALLED_KONTAKTD, os.path.join(prefix, "bin", "kontaktd")))
            r = subprocess.run(["systemd-analyze", "verify", unit], capture_output=True, text=True)
            self.assertEqual((r.returncode, r.stdout + r.stderr), (0, ""))
            r = subprocess.run(["systemd-analyze", "security", "--offline=yes", unit],
                               capture_output=True, text=True)
            m = re.search(r"Overall exposure level for kontaktd.service: ([\d.]+) (\w+)", r.stdout)
            self.assertIsNotNone(m, r.stdout + r.stderr)
            self.assertLessEqual(float(m.group(1)), MAX_EXPOSURE, m.group(0))
            for directive in ("DynamicUser=yes", "NoNewPrivileges=yes", "ProtectSystem=strict",
                              "StateDirectory=kontaktd"):
                self.assertIn(directive, self.text)

    def test_its_environment_is_known_and_the_daemon_serves_with_it(self):
        env = unit_environment(self.text)
        self.assertEqual(env["KONTAKTD_DATA_DIR"], "/var/lib/kontaktd")  # = StateDirectory
        with Installed() as prefix:
            kontaktd = os.path.join(prefix, "bin", "kontaktd")
            self.assertLessEqual(set(env), known_variables(kontaktd))
            serves_with(self, kontaktd, env)


class ContainerfileTest(unittest.TestCase):
    def setUp(self):
        with open(CONTAINERFILE) as f:
            self.text = f.read()

    def test_built_by_the_projects_scripts_and_installed(self):
        run = " ".join(re.findall(r"^RUN\s+((?:.*\\\n)*.*)$", self.text, re.M))
        for step in ("bash deploy/install-deps.sh", "bash deploy/build.sh", "cmake --install build"):
            self.assertIn(step, run)
        self.assertIn(f'CMD ["{INSTALLED_KONTAKTD}"]', self.text)
        self.assertRegex(self.text, r"(?m)^USER kontakt$")

    def test_its_environment_is_known_and_the_daemon_serves_with_it(self):
        env = container_environment(self.text)
        self.assertEqual(set(env), {"KONTAKTD_BIND", "KONTAKTD_PORT", "KONTAKTD_DATA_DIR"})
        with Installed() as prefix:
            kontaktd = os.path.join(prefix, "bin", "kontaktd")
            self.assertLessEqual(set(env), known_variables(kontaktd))
            serves_with(self, kontaktd, env)


if __name__ == "__main__":
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--build", required=True)
    args, rest = p.parse_known_args()
    BUILD = os.path.abspath(args.build)
    unittest.main(argv=[sys.argv[0]] + rest, verbosity=2)
