"""Start a pvserver under MPI, run a pvpython client against it, stop the server.

    python3 RunWithPvserver.py --ranks 2 --pvserver pvserver --pvpython pvpython \\
        -- CLIENT_SCRIPT [ARGS...]

The client gets --server localhost:PORT appended. Every process runs under a time limit
(an MPI start that hangs must fail the test, not stall CI). Exit status: the client's, or
1 when the server does not come up.
"""

import argparse
import os
import signal
import socket
import subprocess
import sys
import threading
import time


def free_port():
    with socket.socket() as probe:
        probe.bind(("localhost", 0))
        return probe.getsockname()[1]


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--ranks", type=int, default=2)
    parser.add_argument("--pvserver", default="pvserver")
    parser.add_argument("--pvpython", default="pvpython")
    parser.add_argument("--timeout", type=float, default=240.0)
    parser.add_argument("client", nargs=argparse.REMAINDER)
    args = parser.parse_args()
    client = [a for a in args.client if a != "--"]
    port = free_port()
    server = subprocess.Popen(
        ["mpiexec", "--allow-run-as-root", "--oversubscribe", "-np", str(args.ranks),
         args.pvserver, "--disable-xdisplay-test", "--server-port=%d" % port],
        stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, start_new_session=True)
    try:
        deadline = time.monotonic() + 60.0
        ready = False
        while time.monotonic() < deadline:
            line = server.stdout.readline()
            if not line:
                break
            print("[pvserver] " + line.rstrip())
            if "Accepting connection" in line:
                ready = True
                break
        if not ready:
            print("ERROR: pvserver did not start on port %d" % port)
            return 1
        # Keep draining the server's output: a full pipe would block it mid-render.
        threading.Thread(target=lambda: [print("[pvserver] " + l.rstrip())
                                         for l in server.stdout], daemon=True).start()
        result = subprocess.run(
            [args.pvpython, "--force-offscreen-rendering"] + client +
            ["--server", "localhost:%d" % port],
            timeout=args.timeout)
        return result.returncode
    except subprocess.TimeoutExpired:
        print("ERROR: the client ran past %g s" % args.timeout)
        return 1
    finally:
        stop(server)


def stop(server):
    """pvserver exits by itself once its client disconnects. A signal that arrives during its
    MPI finalize (slow on a loaded machine) makes Loguru print a FATL line, which fails the
    test although every check passed: signal it only when it is still there after a grace
    period (a failed start, a client that hung or crashed)."""
    try:
        server.wait(timeout=30)
        return
    except subprocess.TimeoutExpired:
        pass
    os.killpg(server.pid, signal.SIGTERM)
    try:
        server.wait(timeout=10)
    except subprocess.TimeoutExpired:
        os.killpg(server.pid, signal.SIGKILL)


if __name__ == "__main__":
    sys.exit(main())
