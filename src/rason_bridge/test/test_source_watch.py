"""rason_mas's ~expected_sources: a source not heard within ~expect_within of the agents' start
is named once, through the perception pump's warnings; one heard in time never is."""
from rason_bridge.coalesce import PerceptionCoalescer
from rason_bridge.params import read_settings
from rason_bridge.perception_pump import PerceptionPump
from rason_bridge.source_watch import SourceWatch


class Clock(object):
    def __init__(self):
        self.now = 100.0

    def __call__(self):
        return self.now


def pump_watching(expected, within, clock):
    warned = []
    pump = PerceptionPump(PerceptionCoalescer(max_sources=10, max_source_length=256), lambda *m: None,
                          release_memory=lambda: None, warn=lambda f, *a: warned.append(f % a),
                          error=lambda *a: None, clock=clock, watch=SourceWatch(expected, within, clock=clock))
    pump._watch.start()
    return pump, warned


def test_a_silent_expected_source_is_named_once_after_the_wait():
    clock = Clock()
    pump, warned = pump_watching(['battery', 'pose'], 10.0, clock)
    pump.put('pose', ['at(1)'], 1)
    clock.now += 9.9
    pump.step()
    assert warned == []
    clock.now += 0.1
    pump.step()
    assert warned == ["perception source 'battery' not heard within 10 s of the start (~expected_sources): "
                      "nothing has published it on jason/perception; is its synthesizer running, and does it "
                      "read the right topic with the right type (see its warnings)?"]
    clock.now += 100
    pump.step()
    assert len(warned) == 1, 'once'


def test_nothing_is_expected_by_default_and_a_source_heard_in_time_is_never_named():
    clock = Clock()
    pump, warned = pump_watching([], 1.0, clock)
    clock.now += 50
    pump.step()
    pump, warned = pump_watching(['pose'], 1.0, clock)
    pump.put('pose', ['at(1)'], 1)
    clock.now += 50
    pump.step()
    assert warned == []


def test_the_watch_waits_for_the_start():
    clock = Clock()
    watch = SourceWatch(['pose'], 1.0, clock=clock)
    clock.now += 50
    assert watch.overdue() == []
    watch.start()
    clock.now += 1
    assert len(watch.overdue()) == 1


def test_the_parameters():
    s = read_settings(lambda name, default: default, '/tmp')
    assert (s.expected_sources, s.expect_within) == ([], 10.0)
    s = read_settings(lambda name, default: {'expected_sources': ['battery'], 'expect_within': 3}.get(name, default),
                      '/tmp')
    assert (s.expected_sources, s.expect_within) == (['battery'], 3.0)
