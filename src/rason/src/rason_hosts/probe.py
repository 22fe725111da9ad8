"""Small network probes to measure the harness's links from inside a namespace.

  python3 -m rason_hosts.probe udp-echo --bind ADDR [--port P]      prints "ready PORT"
  python3 -m rason_hosts.probe udp-probe --to ADDR:PORT --count N    prints JSON {sent, received}
  python3 -m rason_hosts.probe tcp-echo --bind ADDR [--port P]      prints "ready PORT"
  python3 -m rason_hosts.probe tcp-rtt --to ADDR:PORT --count N      prints JSON {rtts_ms,
                                                                     median_ms}
"""
import argparse
import json
import select
import socket
import socketserver
import statistics
import struct
import sys
import time

from .addresses import check_bind_address, split_host_port


def udp_echo(bind, port):
    sock = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
    sock.bind((check_bind_address(bind), port))
    print('ready %d' % sock.getsockname()[1], flush=True)
    while True:
        data, peer = sock.recvfrom(2048)
        sock.sendto(data, peer)


def udp_probe(target, count, interval_s=0.001, linger_s=1.0):
    """Send count numbered datagrams, paced, and count the distinct echoes.

    Echoes are collected while sending and for linger_s after the last one.
    """
    sock = socket.socket(socket.AF_INET, socket.SOCK_DGRAM)
    sock.connect(target)
    sock.setblocking(False)
    echoed = set()

    def collect(until):
        while True:
            left = until - time.monotonic()
            if left <= 0:
                return
            ready, _, _ = select.select([sock], [], [], left)
            if not ready:
                return
            try:
                data = sock.recv(2048)
            except (BlockingIOError, ConnectionRefusedError):
                continue
            if len(data) >= 4:
                echoed.add(struct.unpack('!I', data[:4])[0])

    for seq in range(count):
        try:
            sock.send(struct.pack('!I', seq) + b'probe')
        except (BlockingIOError, ConnectionRefusedError):
            pass
        collect(time.monotonic() + interval_s)
    collect(time.monotonic() + linger_s)
    return {'sent': count, 'received': len(echoed)}


class _EchoHandler(socketserver.BaseRequestHandler):
    def handle(self):
        self.request.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)
        while True:
            data = self.request.recv(4096)
            if not data:
                return
            self.request.sendall(data)


class _ThreadingTCPServer(socketserver.ThreadingTCPServer):
    allow_reuse_address = True
    daemon_threads = True


def tcp_echo(bind, port):
    server = _ThreadingTCPServer((check_bind_address(bind), port), _EchoHandler)
    print('ready %d' % server.server_address[1], flush=True)
    server.serve_forever()


def tcp_rtt(target, count, timeout_s=10.0):
    """Round trips of one byte over one TCP connection (connection set-up not counted)."""
    with socket.create_connection(target, timeout=timeout_s) as sock:
        sock.setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)
        rtts = []
        for _ in range(count):
            start = time.monotonic()
            sock.sendall(b'x')
            if sock.recv(1) != b'x':
                raise ConnectionError('echo server closed the connection')
            rtts.append((time.monotonic() - start) * 1000.0)
    return {'rtts_ms': rtts, 'median_ms': statistics.median(rtts)}


def main(argv=None):
    parser = argparse.ArgumentParser(description='network probes for rason_hosts')
    sub = parser.add_subparsers(dest='command', required=True)
    for name in ('udp-echo', 'tcp-echo'):
        server = sub.add_parser(name)
        server.add_argument('--bind', required=True)
        server.add_argument('--port', type=int, default=0)
    probe = sub.add_parser('udp-probe')
    probe.add_argument('--to', required=True)
    probe.add_argument('--count', type=int, default=500)
    probe.add_argument('--interval-ms', type=float, default=1.0)
    probe.add_argument('--linger-s', type=float, default=1.0)
    rtt = sub.add_parser('tcp-rtt')
    rtt.add_argument('--to', required=True)
    rtt.add_argument('--count', type=int, default=10)
    args = parser.parse_args(argv)
    if args.command == 'udp-echo':
        udp_echo(args.bind, args.port)
    elif args.command == 'tcp-echo':
        tcp_echo(args.bind, args.port)
    elif args.command == 'udp-probe':
        result = udp_probe(split_host_port(args.to), args.count, args.interval_ms / 1000.0,
                           args.linger_s)
        print(json.dumps(result), flush=True)
    else:
        print(json.dumps(tcp_rtt(split_host_port(args.to), args.count)), flush=True)
    return 0


if __name__ == '__main__':
    sys.exit(main())
