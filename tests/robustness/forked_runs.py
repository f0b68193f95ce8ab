"""The robustness suite's runs of ./simulate, forked from build/simulate_server
(tests/simulate_server.cpp) instead of each started anew.

A new ./simulate process spends about 85 ms of CPU before its main (the dynamic loader binding
SimGrid's, ns-3's, Embree's and Assimp's libraries, their static start-up, the allocator's), and
most of the suite's cases are refusals that take a few ms after it: forked from a server that
has started once, a case costs about a third (`run.py --only options`, 175 cases: 29 s of CPU
with new processes, 11 s forked). The child runs ./simulate's main (ncube::simulate_main) from
the case's arguments in the process a new ./simulate would be: its own session, the case's
folder, environment, descriptors and limits (address space, core, file size), and default
signal dispositions; a case that ended before SimGrid started skips the libraries' static
destructors at its exit (tests/simulate_server.cpp says why). The binary's own start-up and
exit are tried by the suite's other tests, which run build/simulate.

A `Run` stands for one case: `pid` (the leader of its session), `poll()` and `wait(timeout)`,
then `code` (the exit code, or minus the signal), `maxrss_kb`, and `stdout` and `stderr` when
captured. Servers are kept, one for each run at a time, and started as needed."""
import atexit
import json
import os
import select
import socket
import subprocess
import threading
from pathlib import Path

_idle = {}           # server binary -> servers not running a case
_lock = threading.Lock()


def server_binary(simulate):
    """The server beside `simulate`, or None (another build of ./simulate, none built, or one
    linked before the libraries both link were last built, as after `cmake --build build
    --target simulate`: it would run older code): the caller then starts ./simulate itself."""
    simulate = Path(simulate)
    server = simulate.parent / "simulate_server"
    if simulate.name != "simulate" or not os.access(server, os.X_OK):
        return None
    try:
        built = server.stat().st_mtime_ns
        if any(built < library.stat().st_mtime_ns
               for library in simulate.parent.glob("libncube*.a")):
            return None
    except OSError:
        return None
    return server


class _Server:
    def __init__(self, binary):
        self.socket, theirs = socket.socketpair(socket.AF_UNIX, socket.SOCK_SEQPACKET)
        self.process = subprocess.Popen([str(binary), str(theirs.fileno())],
                                        pass_fds=[theirs.fileno()], stdin=subprocess.DEVNULL,
                                        stdout=subprocess.DEVNULL)
        theirs.close()

    def answer(self, timeout=None):
        ready, _, _ = select.select([self.socket], [], [], timeout)
        if not ready:
            return None
        text = self.socket.recv(256).decode()
        if not text:
            raise OSError(f"simulate_server ended (exit {self.process.wait()})")
        return text.split()


def _take(binary):
    with _lock:
        idle = _idle.setdefault(binary, [])
        if idle:
            return idle.pop()
    return _Server(binary)


def _give_back(binary, server):
    with _lock:
        _idle[binary].append(server)


@atexit.register
def _stop_servers():
    """Each idle server ends at its socket's close; waited for, so that none outlives the suite
    (and their cases' CPU is counted as this process's children's)."""
    with _lock:
        servers = [server for idle in _idle.values() for server in idle]
        _idle.clear()
    for server in servers:
        server.socket.close()
    for server in servers:
        try:
            server.process.wait(timeout=10)
        except subprocess.TimeoutExpired:
            server.process.kill()
            server.process.wait()


def _read_all(fd, into):
    with os.fdopen(fd, "rb") as stream:
        into.append(stream.read())


class Run:
    """One case of ./simulate (argv[1:] `args`), forked from the server beside `simulate`."""

    def __init__(self, simulate, args, *, cwd, env, as_bytes, fsize_bytes=0, ignore_xfsz=False,
                 stdin=None, capture_stdout=False):
        self.binary = server_binary(simulate)
        self.code, self.maxrss_kb, self.stdout = None, 0, b""
        self._out, self._err, self._readers = [], [], []
        null = os.open(os.devnull, os.O_RDWR)
        err_read, err_write = os.pipe()
        out_read, out_write = os.pipe() if capture_stdout else (None, null)
        request = {"args": [str(a) for a in args], "cwd": str(cwd),
                   "env": {k: v for k, v in env.items()}, "as_bytes": int(as_bytes),
                   "fsize_bytes": int(fsize_bytes), "ignore_xfsz": bool(ignore_xfsz)}
        self._server = _take(self.binary)
        try:
            socket.send_fds(self._server.socket, [json.dumps(request).encode()],
                            [stdin if stdin is not None else null, out_write, err_write])
            answer = self._server.answer(timeout=60)
        finally:
            for fd in {null, err_write, out_write}:
                os.close(fd)
        if not answer or answer[0] != "pid" or int(answer[1]) <= 0:
            raise OSError(f"simulate_server did not start the case: {answer}")
        self.pid = int(answer[1])
        for fd, into in ((err_read, self._err), (out_read, self._out)):
            if fd is not None:
                reader = threading.Thread(target=_read_all, args=(fd, into), daemon=True)
                reader.start()
                self._readers.append(reader)

    def poll(self):
        return self.wait(0)

    def wait(self, timeout=None):
        """True once the case has ended (then code, maxrss_kb, stdout and stderr are set)."""
        if self.code is not None:
            return True
        answer = self._server.answer(timeout)
        if answer is None:
            return False
        _, status, _, maxrss = answer
        self.code = os.waitstatus_to_exitcode(int(status))
        self.maxrss_kb = int(maxrss)
        _give_back(self.binary, self._server)
        for reader in self._readers:
            reader.join(timeout=5)
        self.stdout = b"".join(self._out)
        return True

    @property
    def stderr(self):
        return b"".join(self._err)


def check_output(simulate, args, *, cwd, env):
    """./simulate ARGS as subprocess.check_output runs a program: forked from the server beside
    `simulate` when a current one is built, else started anew; its standard output (bytes), or
    CalledProcessError when it fails (its standard error then written to this process's)."""
    if not server_binary(simulate):
        return subprocess.run([str(simulate), *map(str, args)], check=True, cwd=cwd, env=env,
                              stdout=subprocess.PIPE).stdout
    run = Run(simulate, args, cwd=cwd, env=env, as_bytes=1 << 50, capture_stdout=True)
    run.wait()
    if run.code != 0:
        os.write(2, run.stderr)
        raise subprocess.CalledProcessError(run.code, [str(simulate), *map(str, args)])
    return run.stdout
