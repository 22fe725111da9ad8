"""The one place that hands rason_mas's settings to Java (the ports of ``rason.bridge.Bridge``,
its ``InputLimits`` and its ``rason.infra.RasonLocalMAS``): a change of the Java API is made here only.
No rospy; the JVM must be running (:func:`rason_bridge.jvm.start_jvm`)."""
import jpype

from rason_bridge.fleet_auth import OFF
from rason_bridge.params import MQTT, ParamError, seconds_to_nanos

#: ~param -> the InputLimits setter it sets.
INPUT_LIMIT_SETTERS = {
    'max_literal_length': 'setMaxLiteralLength',
    'max_content_length': 'setMaxContentLength',
    'max_nesting': 'setMaxNesting',
    'max_term_depth': 'setMaxTermDepth',
    'max_literals': 'setMaxLiterals',
    'max_sources': 'setMaxSources',
}


class FleetKeyError(RuntimeError):
    """Fleet authentication is required and no usable key could be loaded (the text says why)."""


def bridge():
    """A new Java ``Bridge``: the composition root of the agents this process hosts."""
    return jpype.JClass('rason.bridge.Bridge')()


def _nanos(settings, name):
    return seconds_to_nanos(name, getattr(settings, name))


def push(java_bridge, settings, mas_id, incarnation):
    """Everything but the fleet key, before the project is loaded.

    :param settings: :data:`rason_bridge.params.Settings`
    :raises ParamError: a value Java refuses (``perception_manager``, ``trust``), saying which and why
    """
    actions, perception, fleet = java_bridge.actions(), java_bridge.perception(), java_bridge.fleet()
    actions.setTimeoutNanos(_nanos(settings, 'action_timeout'))
    actions.setDecomposerGraceNanos(_nanos(settings, 'decomposer_grace'))
    perception.setTtlNanos(_nanos(settings, 'perception_ttl'))
    fleet.setPresenceTimeoutNanos(_nanos(settings, 'presence_timeout'))
    fleet.setAskTimeoutNanos(_nanos(settings, 'ask_timeout'))
    fleet.setMessageTtlNanos(_nanos(settings, 'message_ttl'))
    fleet.setPresenceBeliefs(settings.presence_beliefs)
    try:
        perception.setDefaultManager(settings.perception_manager)
    except jpype.JException as e:
        raise ParamError('perception_manager: %s' % e.getMessage())
    push_input_limits(java_bridge.limits(), settings)
    java_bridge.warnings().setPeriodNanos(_nanos(settings, 'warning_period'))
    push_trust(java_bridge, settings.trust)
    if settings.mind_period > 0:
        java_bridge.mind().setLimits(settings.mind_max_items, settings.mind_max_chars)
        java_bridge.mind().setPeriodNanos(0)  # read only once somebody subscribes
    # Between processes: the node name is the MAS id, the start time tells a restarted process from the one before.
    fleet.setMasId(mas_id)
    fleet.setIncarnation(incarnation)


def push_input_limits(limits, settings):
    """The ``max_*`` settings into Java's ``InputLimits``."""
    for name, setter in INPUT_LIMIT_SETTERS.items():
        getattr(limits, setter)(getattr(settings, name))


def push_trust(java_bridge, rules):
    """The ``trust`` rules (``(agent, group, who)``) into Java's ``TrustPolicy``.

    :raises ParamError: a rule Java refuses, saying which and why
    """
    for agent, group, who in rules:
        try:
            java_bridge.fleet().setTrust(agent, group, who)
        except jpype.JException as e:
            raise ParamError('trust: %s/%s: %s' % (agent, group, e.getMessage()))


def push_auth(java_bridge, settings):
    """Sign and check messages and presence with the fleet key, or not at all.

    :raises FleetKeyError: authentication is required and the key cannot be loaded
    """
    if settings.fleet_auth == OFF:
        java_bridge.fleet().authOff()
        return
    java_bridge.fleet().setAuthWindowNanos(_nanos(settings, 'auth_window'))
    try:
        if settings.fleet_key is not None:
            java_bridge.fleet().requireKeyText(settings.fleet_key, '~fleet_key')
        else:
            java_bridge.fleet().requireKeyFile(settings.fleet_key_file)
    except jpype.JException as e:
        raise FleetKeyError(str(e.getMessage()))


def use_channel(java_bridge, settings):
    """With ``fleet_channel: mqtt``, the fleet goes through the broker from Java (after :func:`push`
    and :func:`push_auth`, before the agents start); with ``ros``, nothing changes.

    :raises ParamError: MQTT settings Java refuses, saying which and why
    """
    if settings.fleet_channel != MQTT:
        return None
    mqtt_settings = jpype.JClass('rason.messaging.mqtt.MqttSettings')
    try:
        return java_bridge.useMqtt(mqtt_settings(
            settings.mqtt_url, settings.mqtt_prefix, int(settings.message_ttl),
            seconds_to_nanos('presence_period', settings.presence_period), settings.mqtt_username,
            settings.mqtt_password_file, settings.mqtt_ca_file))
    except jpype.JException as e:
        raise ParamError('fleet_channel mqtt: %s' % e.getMessage())


def load_mas(java_bridge, settings, mas2j_path):
    """Load the project and create its agents (named with ``agent_prefix``); returns the Java MAS.

    :raises RuntimeError: the project cannot be loaded (Java's message)
    """
    mas = java_bridge.newMas()
    try:
        mas.setAgentPrefix(settings.agent_prefix)
        mas.load(mas2j_path)
        mas.create()
    except jpype.JException as e:
        raise RuntimeError(str(e.getMessage()))
    return mas


def max_source_length():
    """The fixed bound on a perception source's name (Java's ``InputLimits.MAX_SOURCE_LENGTH``)."""
    return int(jpype.JClass('rason.core.InputLimits').MAX_SOURCE_LENGTH)
