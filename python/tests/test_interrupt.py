"""Long work releases the GIL, and Ctrl+C (SIGINT) ends it with KeyboardInterrupt."""
import os
import signal
import subprocess
import sys
import textwrap
import threading
import time

from conftest import sphere

# A resampling that runs for many seconds here: a 100k-point sphere on a fine grid (about a million points out).
LONG_WORK = textwrap.dedent("""
    import sys, time
    sys.path.insert(0, {tests!r})
    import amls
    from conftest import sphere
    points, normals = sphere(100000)
    print("started", flush=True)
    try:
        amls.resample(points, normals, grid=800, uniform_support=True, threads=2)
        print("finished", flush=True)
    except KeyboardInterrupt:
        print("interrupted %.3f" % time.monotonic(), flush=True)
""")


def test_ctrl_c_stops_a_long_resample_with_keyboard_interrupt():
    child = subprocess.Popen([sys.executable, "-c", LONG_WORK.format(tests=os.path.dirname(__file__))],
                             stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=dict(os.environ))
    assert child.stdout.readline().strip() == "started"
    time.sleep(1.5)  # into the resampling, which takes far longer
    assert child.poll() is None, "the work ended before the signal; the case is too short"
    sent = time.monotonic()
    child.send_signal(signal.SIGINT)
    try:
        out, err = child.communicate(timeout=60)  # only a guard against a hang
    except subprocess.TimeoutExpired:
        child.kill()
        raise AssertionError("still running 60 s after SIGINT")
    assert "finished" not in out, out + err
    line = out.strip().splitlines()[-1]
    assert line.startswith("interrupted"), out + err
    # For the log (pytest -s): how long the work took to stop; not asserted, the machine may be busy.
    print(f"stopped {float(line.split()[1]) - sent:.3f} s after SIGINT")


def test_other_python_threads_run_during_long_work(amls):
    ticks = []
    done = threading.Event()

    def tick():
        while not done.is_set():
            ticks.append(time.monotonic())
            time.sleep(0.005)

    points, normals = sphere(20000)
    ticker = threading.Thread(target=tick)
    ticker.start()
    time.sleep(0.05)
    start = time.monotonic()
    amls.resample(points, normals, grid=400, uniform_support=True)
    end = time.monotonic()
    done.set()
    ticker.join()
    during = [t for t in ticks if start < t < end]
    # Holding the GIL, the call would let the ticker in at most once or twice (at its edges).
    assert end - start > 0.2, "the call is too short to tell"
    assert len(during) >= 20, f"{len(during)} ticks in {end - start:.2f} s"
