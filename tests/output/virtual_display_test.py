"""Tests of virtual_display.py, the X server that ParaView's check renders on (issue 29).

Usage: python3 virtual_display_test.py   (CTest runs it; exits 1 at the first failed check)

1. A connection that follows the close of the only other one is accepted: 2 000 open/close
   pairs back to back, 0 refused. An X server without -noreset resets when its last client
   leaves and refuses ~3 % of them (62 of 2 000 measured), which is how ParaView's render
   failed with "bad X server connection".
2. The command's exit status comes back; a missing Xvfb is exit 125 with a message.
3. Whatever ends the script — the command's exit, SIGTERM, SIGKILL — the server stops.
"""
import ctypes
import os
import signal
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
WRAPPER = [sys.executable, os.path.join(HERE, "virtual_display.py")]

OPEN_CLOSE = """
import ctypes, sys
x11 = ctypes.cdll.LoadLibrary("libX11.so.6")
x11.XOpenDisplay.restype = ctypes.c_void_p
refused = 0
for _ in range(2000):
    display = x11.XOpenDisplay(None)
    if not display:
        refused += 1
        continue
    x11.XCloseDisplay(ctypes.c_void_p(display))
print(refused)
"""


def check(condition, what):
    print(("ok   " if condition else "FAIL ") + what, flush=True)
    if not condition:
        sys.exit(1)


def wait_until(condition, limit=60.0):
    """Polls `condition` until it holds or `limit` seconds pass. The limit only bounds a failure;
    a passing run returns as soon as the condition holds, however busy the machine."""
    end = time.monotonic() + limit
    while not condition():
        if time.monotonic() > end:
            return False
        time.sleep(0.05)
    return True


def server_alive(display):
    x11 = ctypes.cdll.LoadLibrary("libX11.so.6")
    x11.XOpenDisplay.restype = ctypes.c_void_p
    connection = x11.XOpenDisplay(display.encode())
    if connection:
        x11.XCloseDisplay(ctypes.c_void_p(connection))
    return bool(connection)


def running(pid):
    """Whether process `pid` runs (a zombie has ended; other tests may start servers meanwhile,
    even on the same display number, so the server is told by its process, not its display)."""
    try:
        with open(f"/proc/{pid}/stat") as file:
            return file.read().rsplit(")", 1)[1].split()[0] != "Z"
    except FileNotFoundError:
        return False


def started(ending):
    """Runs the wrapper on a command that writes its DISPLAY and server to a file and sleeps;
    returns the wrapper and the server's process id once the command runs."""
    folder = tempfile.mkdtemp()
    report = os.path.join(folder, "display")
    wrapper = subprocess.Popen(WRAPPER + ["sh", "-c", f'echo "$DISPLAY $VIRTUAL_DISPLAY_SERVER" > {report}.part && '
                                          f'mv {report}.part {report} && exec sleep 600'])
    check(wait_until(lambda: os.path.exists(report)), f"{ending}: the command runs under the server")
    with open(report) as file:
        display, server = file.read().split()
    check(server_alive(display) and running(server), f"{ending}: a client connects to {display}")
    return wrapper, server


# 1. The reset refusal.
result = subprocess.run(WRAPPER + [sys.executable, "-c", OPEN_CLOSE], capture_output=True, text=True)
check(result.returncode == 0, f"the open/close loop ran (status {result.returncode}) {result.stderr}")
check(result.stdout.strip() == "0", f"{result.stdout.strip()} of 2000 connections refused, expected 0")

# 2. Exit statuses; the server stops when the command exits.
ended = subprocess.run(WRAPPER + ["sh", "-c", 'echo "$VIRTUAL_DISPLAY_SERVER"; exit 3'],
                       capture_output=True, text=True)
check(ended.returncode == 3, f"the command's status 3 comes back ({ended.returncode})")
check(not running(ended.stdout.strip()), f"the command exited: the server (process {ended.stdout.strip()}) has stopped")
empty = tempfile.mkdtemp()
missing = subprocess.run(WRAPPER + ["true"], env=dict(os.environ, PATH=empty), capture_output=True, text=True)
check(missing.returncode == 125 and "Xvfb is not installed" in missing.stderr,
      f"without Xvfb: status {missing.returncode}, '{missing.stderr.strip()}'")

# 3. A termination request unwinds: status 128 + 15, server and command stopped before it returns.
wrapper, server = started("SIGTERM")
wrapper.send_signal(signal.SIGTERM)
check(wrapper.wait() == 128 + signal.SIGTERM, f"SIGTERM: status {wrapper.returncode}")
check(not running(server), f"SIGTERM: the server (process {server}) has stopped")

# A kill cannot be caught: the kernel sends the server its parent-death signal.
wrapper, server = started("SIGKILL")
wrapper.kill()
wrapper.wait()
check(wait_until(lambda: not running(server)), f"SIGKILL: the server (process {server}) has stopped")
