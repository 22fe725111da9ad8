"""The settings reach Java through java_config alone, by methods Java's Bridge has, in its units."""
import jpype
import pytest

from rason_bridge import java_config
from rason_bridge.jvm import start_jvm
from rason_bridge.params import ParamError, read_settings

start_jvm()
Bridge = jpype.JClass('rason.bridge.Bridge')
InputLimits = jpype.JClass('rason.bridge.InputLimits')


class RecordingBridge(object):
    """Records each call; ``limits()`` is a real InputLimits."""

    def __init__(self):
        self.calls = []
        self.input_limits = InputLimits()

    def limits(self):
        self.calls.append(('limits',))
        return self.input_limits

    def __getattr__(self, name):
        return lambda *args: self.calls.append((name,) + args)


def settings(**given):
    return read_settings(lambda name, default: given.get(name, default), '/home/robot/.ros')


def pushed(**given):
    bridge = RecordingBridge()
    java_config.push(bridge, settings(**given), '/r1/rason_mas', 42)
    return bridge


def test_every_method_called_is_one_of_the_java_bridges():
    bridge = pushed(trust={'bob': {'tell': 'all'}})
    java_config.push_auth(bridge, settings())
    java_config.push_auth(bridge, settings(fleet_auth='off'))
    java_config.push_auth(bridge, settings(fleet_key='k' * 40))
    names = set(call[0] for call in bridge.calls)
    assert {'setTrust', 'setMindLimits', 'requireFleetKeyFile', 'requireFleetKeyText', 'fleetAuthOff'} <= names
    assert [n for n in names if not hasattr(Bridge, n)] == []


def test_durations_go_in_nanoseconds_and_identity_last():
    calls = pushed(action_timeout=1.5, ask_timeout=0, decomposer_grace=0.25).calls
    assert ('setActionTimeoutNanos', 1500000000) in calls
    assert ('setAskTimeoutNanos', 0) in calls
    assert ('setDecomposerGraceNanos', 250000000) in calls
    assert ('setPerceptionTtlNanos', 2000000000) in calls and ('setPresenceTimeoutNanos', 2000000000) in calls
    assert ('setPresenceBeliefs', True) in calls and ('setDefaultPerceptionManager', 'per_source') in calls
    assert calls[-2:] == [('setMasId', '/r1/rason_mas'), ('setIncarnation', 42)]


def test_input_limits_and_mind_bounds():
    bridge = pushed(max_sources=7, mind_max_items=9)
    assert bridge.input_limits.maxSources() == 7
    assert ('setMindLimits', 9, 500) in bridge.calls and ('setMindPeriodNanos', 0) in bridge.calls
    assert not [c for c in pushed(mind_period=0).calls if c[0].startswith('setMind')]


def test_the_auth_window_goes_with_a_required_key_only():
    bridge = RecordingBridge()
    java_config.push_auth(bridge, settings(auth_window=5))
    assert bridge.calls == [('setAuthWindowNanos', 5000000000),
                            ('requireFleetKeyFile', '/home/robot/.ros/rason/fleet.key')]
    bridge = RecordingBridge()
    java_config.push_auth(bridge, settings(fleet_auth='off'))
    assert bridge.calls == [('fleetAuthOff',)]


class RefusingBridge(RecordingBridge):
    """Java's own checks of the perception manager and the key file; everything else recorded."""

    def setDefaultPerceptionManager(self, spec):
        Bridge.get().setDefaultPerceptionManager(spec)  # refuses before it changes anything

    def requireFleetKeyFile(self, path):
        Bridge.get().requireFleetKeyFile(path)  # refuses before it changes anything


def test_javas_refusals_name_the_parameter():
    with pytest.raises(ParamError, match="^perception_manager: perception manager 'fancier' is neither"):
        java_config.push(RefusingBridge(), settings(perception_manager='fancier'), '/r1/rason_mas', 1)
    with pytest.raises(java_config.FleetKeyError, match='/nonexistent/fleet.key does not exist'):
        java_config.push_auth(RefusingBridge(), settings(fleet_key_file='/nonexistent/fleet.key'))
