"""gecko.progress: the bar's rate and ETA, on a clock the test drives."""
import io

import pytest

from gecko.progress import Progress, format_duration


class Tty(io.StringIO):
    def isatty(self):
        return True


class Clock:
    def __init__(self):
        self.t = 100.0

    def __call__(self):
        return self.t


def test_rate_and_eta_follow_the_mean_rate_so_far():
    clock = Clock()
    tty = Tty()
    p = Progress(100, "sweep", stream=tty, delay=0, clock=clock)
    assert p.eta() != p.eta()  # no time has passed: no estimate (NaN)
    clock.t += 4.0
    p.advance(20, "designs")
    assert p.rate() == 5.0
    assert p.eta() == 16.0
    line = tty.getvalue()
    assert line.startswith("\rsweep [######........................] 20/100 designs")
    assert line.rstrip().endswith("5/s  ETA 0:16")
    clock.t += 4.0
    p.advance(80)
    assert p.eta() == 0.0
    assert tty.getvalue().rstrip().endswith("12.5/s  ETA 0:00")
    p.close()
    assert tty.getvalue().endswith("\r")


def test_no_estimate_before_time_passes():
    p = Progress(10, "x", stream=Tty(), delay=0, clock=lambda: 0.0)
    p.advance(1)
    assert "--/s  ETA --:--" in p.stream.getvalue()


def test_a_shorter_line_overwrites_the_whole_previous_one():
    clock = Clock()
    tty = Tty()
    p = Progress(3, "x", stream=tty, delay=0, clock=clock)
    clock.t += 1.0
    p.advance(1, "a long description of the step")
    first = tty.getvalue()
    p.advance(1, "")
    second = tty.getvalue()[len(first):]
    assert len(second) == len(first)


@pytest.mark.parametrize("s, text", [(0, "0:00"), (59.4, "0:59"), (61, "1:01"), (3600, "1:00:00"),
                                     (3725, "1:02:05"), (float("nan"), "--:--"), (float("inf"), "--:--"),
                                     (-1, "--:--")])
def test_format_duration(s, text):
    assert format_duration(s) == text


def test_old_import_path_still_works():
    from gecko.scene.runner import Progress as Old
    assert Old is Progress
