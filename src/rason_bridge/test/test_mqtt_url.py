"""The broker address of ~mqtt_url (rason_bridge.mqtt_url), shared by rason_mas and topic_relay."""
import pytest

from rason_bridge.mqtt_url import MqttAddress, parse_mqtt_url


@pytest.mark.parametrize('url, address', [
    ('tcp://127.0.0.1:1883', MqttAddress('127.0.0.1', 1883, False)),
    ('tcp://broker.lan', MqttAddress('broker.lan', 1883, False)),
    ('ssl://broker.lan', MqttAddress('broker.lan', 8883, True)),
    ('ssl://10.0.0.2:9000', MqttAddress('10.0.0.2', 9000, True)),
])
def test_a_broker_address_is_read_with_its_default_port(url, address):
    assert parse_mqtt_url(url) == address


@pytest.mark.parametrize('url, message', [
    ('localhost:1883', 'must be tcp://HOST:PORT'),
    ('http://broker', 'must be tcp://HOST:PORT'),
    ('tcp://', 'must be tcp://HOST:PORT'),
    ('tcp://broker:99999', 'the port is not a number'),
    ('tcp://[bad', ''),
    (1883, 'must be tcp://HOST:PORT'),
])
def test_a_bad_address_is_refused_saying_what_is_wrong(url, message):
    with pytest.raises(ValueError, match=message):
        parse_mqtt_url(url)
