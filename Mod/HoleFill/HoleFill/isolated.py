"""A core call in a process of its own, so that a crash inside a geometry kernel (CGAL, OCCT,
Eigen) takes that process down and not FreeCAD with the user's unsaved work. The labeled fit's
preview died of a SIGSEGV in CGAL's triangulation inside FreeCAD on an ordinary scan region
(issue 25); the core has since been made to refuse such input, and this is the guard that makes a
crash that is still there harmless. The child is FreeCAD's own Python (Debian's python3 of the
same version, never a pyenv one first on PATH) running this file as a script: it imports the
compiled core (HoleFillApp) alone, never FreeCAD, calls one of its functions, and hands the
result back pickled over a pipe. While it runs, `progress` is called about ten times a second
(a progress dialog's callable: False kills the child). A child that dies of a signal, runs past
`timeout` or is cancelled raises HoleFillError saying so; the document was never touched."""
import os
import pickle
import signal
import subprocess
import sys
import time

def _python():
    """The interpreter to run the child with: FreeCAD's executable is not Python."""
    if os.path.basename(sys.executable).startswith("python"):
        return sys.executable
    exact = "/usr/bin/python%d.%d" % sys.version_info[:2]
    return exact if os.path.exists(exact) else "/usr/bin/python3"


def call(function, *args, progress=None, timeout=None, what="the computation"):
    """HoleFillApp.<function>(*args) in a child process; its result, or HoleFillError."""
    import HoleFillApp
    from HoleFillApp import HoleFillError
    env = dict(os.environ, HOLEFILL_CORE_DIR=os.path.dirname(os.path.abspath(HoleFillApp.__file__)))
    child = subprocess.Popen([_python(), os.path.abspath(__file__)], stdin=subprocess.PIPE, stdout=subprocess.PIPE,
                             stderr=subprocess.PIPE, env=env)
    payload = pickle.dumps((function, args), protocol=pickle.HIGHEST_PROTOCOL)
    # Both pipes are read by threads as the child writes (a result past a pipe's 64 KB would
    # block it otherwise), while this loop keeps the GUI's events going through `progress`.
    import threading
    out, err = [], []
    readers = [threading.Thread(target=lambda: out.append(child.stdout.read())),
               threading.Thread(target=lambda: err.append(child.stderr.read()))]
    for r in readers:
        r.start()
    try:
        child.stdin.write(payload)
        child.stdin.close()
    except BrokenPipeError:
        pass
    start = time.time()
    try:
        while child.poll() is None:
            if progress is not None and progress(min(0.95, (time.time() - start) / 10.0)) is False:
                child.kill()
                child.wait()
                raise HoleFillError("%s was cancelled" % what)
            if timeout is not None and time.time() - start > timeout:
                child.kill()
                child.wait()
                raise HoleFillError("%s ran past its %g s and was stopped" % (what, timeout))
            time.sleep(0.05)
    finally:
        for r in readers:
            r.join()
    if child.returncode < 0:
        name = signal.Signals(-child.returncode).name if -child.returncode in signal.Signals._value2member_map_ else str(-child.returncode)
        raise HoleFillError("%s crashed (%s) in a process of its own: FreeCAD and the document are untouched; "
                            "this is a bug in HoleFill, please report it with the input" % (what, name))
    try:
        ok, value = pickle.loads(out[0])
    except Exception:
        raise HoleFillError("%s ended without a result (exit %d): %s" % (what, child.returncode, (err[0] or b"").decode(errors="replace")[-400:]))
    if not ok:
        raise HoleFillError(value)
    return value


def _serve():
    """The child: one call read from stdin, its result (or error) written to stdout."""
    sys.path.insert(0, os.environ["HOLEFILL_CORE_DIR"])
    import HoleFillApp
    function, args = pickle.load(sys.stdin.buffer)
    # Fault injection for the tests: the child of this function dies as a crash in the core would.
    if os.environ.get("HOLEFILL_TEST_CRASH_CHILD") == function:
        os.kill(os.getpid(), signal.SIGSEGV)
    try:
        result = (True, getattr(HoleFillApp, function)(*args))
    except Exception as e:  # the core's errors cross as their message
        result = (False, str(e))
    sys.stdout.buffer.write(pickle.dumps(result, protocol=pickle.HIGHEST_PROTOCOL))
    sys.stdout.buffer.flush()


if __name__ == "__main__":
    _serve()
