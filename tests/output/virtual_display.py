"""Runs a command under a virtual X server of its own, and stops that server on every path.

Usage:
    python3 virtual_display.py COMMAND [ARGUMENT...]

COMMAND runs with DISPLAY set to the server and VIRTUAL_DISPLAY_SERVER to its process id. Exits
with COMMAND's status; with 125 and a message on stderr when no server could be started.

Why not xvfb-run (issue 29). Two causes made ParaView's render fail with "bad X server connection":

1. An X server *resets* when its last client disconnects (it closes every listening connection
   while it regenerates), unless it runs with -noreset. ParaView's rendering-capabilities probe
   opens a connection, closes it, and a moment later its render window opens a new one: when the
   probe was the only client, that second connection arrives during the reset and is refused.
   Measured on 2026-11-28: of 2 000 open/close pairs back to back, 62 failed on a server without
   -noreset and 0 on one with it (tests/output/virtual_display_test.py checks it on every run).
   xvfb-run starts Xvfb without -noreset.
2. xvfb-run -a chooses the display number itself by looking for a lock file, before the server
   exists, so two runs may pick the same one; retrying on fixed or random displays only made the
   race rarer.

Here Xvfb chooses its display itself (-displayfd), and writes the number to a pipe only once it
accepts connections, so the command starts when the server is ready, on a display no one else
holds. The server gets SIGTERM when this script ends by any path, SIGKILL included (the kernel's
parent-death signal), and the command likewise.
"""
import ctypes
import os
import select
import signal
import subprocess
import sys

# Seconds Xvfb may take to accept connections. It starts in ~0.1 s on an idle machine; the
# limit only turns a server that never starts into a clear failure instead of a hang.
START_LIMIT = 60.0

PR_SET_PDEATHSIG = 1  # prctl option: the signal a child receives when its parent dies


def die_with_parent():
    """Runs in the child between fork and exec: SIGTERM it when this script ends, even by SIGKILL."""
    ctypes.CDLL(None, use_errno=True).prctl(PR_SET_PDEATHSIG, signal.SIGTERM)


class NoServer(Exception):
    """Xvfb is missing, exited, or did not accept connections in time."""


def start_server():
    """Starts Xvfb; returns (process, display) once it accepts connections."""
    read_end, write_end = os.pipe()
    try:
        server = subprocess.Popen(
            ["Xvfb", "-displayfd", str(write_end), "-noreset", "-nolisten", "tcp",
             "-screen", "0", "1024x768x24"],
            pass_fds=(write_end,), stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL,
            stderr=subprocess.PIPE, preexec_fn=die_with_parent)
    except FileNotFoundError:
        raise NoServer("Xvfb is not installed") from None
    finally:
        os.close(write_end)
    number = b""
    while not number.endswith(b"\n"):
        ready, _, _ = select.select([read_end], [], [], START_LIMIT)
        chunk = os.read(read_end, 16) if ready else b""
        if not chunk:  # the server exited before it was ready, or did not start in time
            stop(server)
            errors = server.stderr.read().decode(errors="replace").strip()
            raise NoServer(f"Xvfb did not accept connections within {START_LIMIT:g} s "
                           f"(exit status {server.returncode}): {errors or 'no message'}")
        number += chunk
    os.close(read_end)
    return server, ":" + number.decode().strip()


def stop(process):
    """Ends a child and reaps it: SIGTERM, then SIGKILL after 10 s."""
    if process.poll() is None:
        process.terminate()
        try:
            process.wait(10)
        except subprocess.TimeoutExpired:
            process.kill()
            process.wait()


def main():
    if len(sys.argv) < 2:
        sys.exit("usage: virtual_display.py COMMAND [ARGUMENT...]")
    # A termination request (ctest's timeout, Ctrl-C) unwinds through the finally blocks below.
    for signal_number in (signal.SIGTERM, signal.SIGINT, signal.SIGHUP):
        signal.signal(signal_number, lambda number, frame: sys.exit(128 + number))
    try:
        server, display = start_server()
    except NoServer as reason:
        print(f"virtual_display: {reason}\nfix: scripts/setup.sh --test installs Debian's xvfb",
              file=sys.stderr)
        return 125
    command = None
    try:
        environment = dict(os.environ, DISPLAY=display, VIRTUAL_DISPLAY_SERVER=str(server.pid))
        command = subprocess.Popen(sys.argv[1:], env=environment, preexec_fn=die_with_parent)
        return command.wait()
    finally:
        if command is not None:
            stop(command)
        stop(server)


if __name__ == "__main__":
    sys.exit(main())
