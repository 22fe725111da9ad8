"""The broker address of ``~mqtt_url``, read once for every Python node that connects
(rason_mas's parameter check, topic_relay); the JVM reads the same form (MqttSettings)."""
import collections
import urllib.parse

MqttAddress = collections.namedtuple('MqttAddress', 'host port tls')

SCHEMES = {'tcp': False, 'mqtt': False, 'ssl': True}      # scheme -> TLS


def parse_mqtt_url(url):
    """:class:`MqttAddress` of ``tcp://HOST[:PORT]`` or ``ssl://HOST[:PORT]`` (1883 and 8883
    by default).

    :raises ValueError: naming what is wrong
    """
    parsed = urllib.parse.urlparse(url) if isinstance(url, str) else None
    if parsed is None or parsed.scheme not in SCHEMES or not parsed.hostname:
        raise ValueError('%r must be tcp://HOST:PORT or ssl://HOST:PORT' % (url,))
    tls = SCHEMES[parsed.scheme]
    try:
        port = parsed.port or (8883 if tls else 1883)
    except ValueError:
        raise ValueError('%r: the port is not a number from 1 to 65535' % (url,))
    return MqttAddress(parsed.hostname, port, tls)
