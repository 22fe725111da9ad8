"""Addresses the harness may use: loopback and 198.18.0.0/15 (RFC 2544, benchmarking) only."""
import ipaddress

BENCHMARK_NET = ipaddress.ip_network('198.18.0.0/15')
# Every run has its own switch namespace, so runs never share a segment and can reuse this subnet.
HOST_SUBNET = ipaddress.ip_network('198.18.0.0/24')


def host_address(index):
    """The address of the index-th host (0-based) of a run."""
    if not 0 <= index < HOST_SUBNET.num_addresses - 2:
        raise ValueError('at most %d hosts per run' % (HOST_SUBNET.num_addresses - 2))
    return str(HOST_SUBNET.network_address + 1 + index)


def check_bind_address(address):
    """Raise ValueError unless address is loopback or inside 198.18.0.0/15."""
    ip = ipaddress.ip_address(address)
    if not (ip.is_loopback or ip in BENCHMARK_NET):
        raise ValueError('refusing to bind %s: only loopback or 198.18.0.0/15 (harness hosts)'
                         % address)
    return address


def split_host_port(text):
    host, _, port = text.rpartition(':')
    if not host:
        raise ValueError('expected HOST:PORT, got %r' % text)
    return host.strip('[]'), int(port)
