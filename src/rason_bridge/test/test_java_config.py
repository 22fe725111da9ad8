"""The settings reach Java through java_config alone, by methods Java's Bridge has, in its units."""
import jpype
import pytest

from rason_bridge import java_config
from rason_bridge.jvm import start_jvm
from rason_bridge.params import ParamError, read_settings

start_jvm()
Bridge = jpype.JClass('rason.bridge.Bridge')
InputLimits = jpype.JClass('rason.core.InputLimits')
#: The ports java_config reaches through the Bridge's accessors, and their Java classes.
PORTS = {'actions': jpype.JClass('rason.action.ActionPort'),
         'perception': jpype.JClass('rason.perception.PerceptionPort'),
         'fleet': jpype.JClass('rason.messaging.FleetPort'),
         'mind': jpype.JClass('rason.mind.MindPort'),
         'warnings': jpype.JClass('rason.core.RateLimitedLog')}


class RecordingPort(object):
    """Records each call as (port.method, args...)."""

    def __init__(self, name, calls):
        self._name = name
        self._calls = calls

    def __getattr__(self, method):
        return lambda *args: self._calls.append(('%s.%s' % (self._name, method),) + args)


class RecordingBridge(object):
    """Records each call on its ports; ``limits()`` is a real InputLimits."""

    def __init__(self):
        self.calls = []
        self.input_limits = InputLimits()
        self.ports = {name: RecordingPort(name, self.calls) for name in PORTS}

    def limits(self):
        self.calls.append(('limits',))
        return self.input_limits

    def __getattr__(self, name):
        if name in PORTS:
            return lambda: self.ports[name]
        raise AttributeError(name)


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
    names = set(call[0] for call in bridge.calls if '.' in call[0])
    assert {'fleet.setTrust', 'mind.setLimits', 'fleet.requireKeyFile', 'fleet.requireKeyText',
            'fleet.authOff'} <= names
    assert [n for n in names if not hasattr(PORTS[n.split('.')[0]], n.split('.')[1])] == []
    assert all(hasattr(Bridge, port) for port in PORTS)


def test_durations_go_in_nanoseconds_and_identity_last():
    calls = pushed(action_timeout=1.5, ask_timeout=0, decomposer_grace=0.25).calls
    assert ('actions.setTimeoutNanos', 1500000000) in calls
    assert ('fleet.setAskTimeoutNanos', 0) in calls
    assert ('actions.setDecomposerGraceNanos', 250000000) in calls
    assert ('perception.setTtlNanos', 2000000000) in calls and ('fleet.setPresenceTimeoutNanos', 2000000000) in calls
    assert ('fleet.setPresenceBeliefs', True) in calls and ('perception.setDefaultManager', 'per_source') in calls
    assert ('warnings.setPeriodNanos', 10000000000) in calls
    assert calls[-2:] == [('fleet.setMasId', '/r1/rason_mas'), ('fleet.setIncarnation', 42)]
    assert ('warnings.setPeriodNanos', 2500000000) in pushed(warning_period=2.5).calls


def test_input_limits_and_mind_bounds():
    bridge = pushed(max_sources=7, mind_max_items=9)
    assert bridge.input_limits.maxSources() == 7
    assert ('mind.setLimits', 9, 500) in bridge.calls and ('mind.setPeriodNanos', 0) in bridge.calls
    assert not [c for c in pushed(mind_period=0).calls if c[0].startswith('mind.')]


def test_the_auth_window_goes_with_a_required_key_only():
    bridge = RecordingBridge()
    java_config.push_auth(bridge, settings(auth_window=5))
    assert bridge.calls == [('fleet.setAuthWindowNanos', 5000000000),
                            ('fleet.requireKeyFile', '/home/robot/.ros/rason/fleet.key')]
    bridge = RecordingBridge()
    java_config.push_auth(bridge, settings(fleet_auth='off'))
    assert bridge.calls == [('fleet.authOff',)]


class RefusingBridge(RecordingBridge):
    """Java's own checks of the perception manager and the key file (a real Bridge's ports);
    everything else recorded."""

    def __init__(self):
        super().__init__()
        real = Bridge()
        self.ports['perception'] = real.perception()
        self.ports['fleet'] = real.fleet()


def test_javas_refusals_name_the_parameter():
    with pytest.raises(ParamError, match="^perception_manager: perception manager 'fancier' is neither"):
        java_config.push(RefusingBridge(), settings(perception_manager='fancier'), '/r1/rason_mas', 1)
    with pytest.raises(java_config.FleetKeyError, match='/nonexistent/fleet.key does not exist'):
        java_config.push_auth(RefusingBridge(), settings(fleet_key_file='/nonexistent/fleet.key'))


class ChannelBridge(object):
    """Records the MQTT settings ``useMqtt`` is given."""

    def __init__(self):
        self.mqtt = []

    def useMqtt(self, mqtt_settings):
        self.mqtt.append(mqtt_settings)
        return 'channel'


def test_the_ros_channel_needs_nothing_and_mqtt_settings_reach_java_in_its_units():
    bridge = ChannelBridge()
    assert java_config.use_channel(bridge, settings()) is None
    assert bridge.mqtt == []
    assert java_config.use_channel(bridge, settings(
        fleet_channel='mqtt', mqtt_url='ssl://broker.lab:8883', mqtt_prefix='lab1', message_ttl=30,
        presence_period=0.25, mqtt_username='robot1', mqtt_password_file='/etc/rason/pw',
        mqtt_ca_file='/etc/rason/ca.pem')) == 'channel'
    (mqtt,) = bridge.mqtt
    assert (str(mqtt.url()), str(mqtt.prefix()), mqtt.messageTtlSeconds(), mqtt.presencePeriodNanos()) == \
        ('ssl://broker.lab:8883', 'lab1/', 30, 250000000)
    assert (str(mqtt.username()), str(mqtt.passwordFile()), str(mqtt.caFile())) == \
        ('robot1', '/etc/rason/pw', '/etc/rason/ca.pem')
    assert (str(mqtt.host()), mqtt.port(), mqtt.tls()) == ('broker.lab', 8883, True)


def test_mqtt_settings_java_refuses_name_the_parameter():
    # an address Python's check lets through and the JVM's URI parser does not
    with pytest.raises(ParamError, match="fleet_channel mqtt: mqtt_url 'tcp://bro ker:1883' is not a URL"):
        java_config.use_channel(ChannelBridge(), settings(fleet_channel='mqtt', mqtt_url='tcp://bro ker:1883'))
