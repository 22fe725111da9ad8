"""A TCP relay that delays every chunk by D ms in each direction, keeping order.

The kernel here has no netem qdisc, so link delay is made in user space: a client connects to
the relay instead of the server; each chunk read from either side is written to the other side
D ms after it was read. A round trip through the relay therefore gains 2*D. D can be changed
while the relay runs through a Unix control socket (a filesystem path, reachable from every
network namespace).

Run: python3 -m rason_hosts.relay --listen ADDR:PORT --target ADDR:PORT --delay-ms D
     [--control PATH]; it prints "listening ADDR PORT" once bound.
"""
import argparse
import asyncio
import os
import signal
import socket
import sys

from .addresses import check_bind_address, split_host_port

CHUNK = 65536
QUEUED_CHUNKS = 256  # per direction; a full queue stops reading, so TCP flow control holds


class DelayRelay:
    def __init__(self, listen, target, delay_ms, control_path=None):
        self.listen = listen
        self.target = target
        self.delay_ms = float(delay_ms)
        self.control_path = control_path
        self._servers = []
        self.address = None

    def set_delay(self, delay_ms):
        if delay_ms < 0:
            raise ValueError('delay must be >= 0')
        self.delay_ms = float(delay_ms)

    async def start(self):
        server = await asyncio.start_server(self._on_client, self.listen[0], self.listen[1])
        self._servers.append(server)
        self.address = server.sockets[0].getsockname()[:2]
        if self.control_path:
            if os.path.exists(self.control_path):
                os.unlink(self.control_path)
            self._servers.append(await asyncio.start_unix_server(self._on_control,
                                                                 self.control_path))
        return self.address

    async def close(self):
        for server in self._servers:
            server.close()
            await server.wait_closed()
        if self.control_path and os.path.exists(self.control_path):
            os.unlink(self.control_path)

    async def _on_control(self, reader, writer):
        try:
            words = (await reader.readline()).decode().split()
            if len(words) == 2 and words[0] == 'delay':
                self.set_delay(float(words[1]))
            elif words != ['get']:
                raise ValueError('expected "delay MS" or "get"')
            writer.write(b'ok %g\n' % self.delay_ms)
        except ValueError as error:
            writer.write(b'error %s\n' % str(error).encode())
        await writer.drain()
        writer.close()

    async def _on_client(self, client_reader, client_writer):
        try:
            server_reader, server_writer = await asyncio.open_connection(*self.target)
        except OSError:
            client_writer.close()
            return
        for writer in (client_writer, server_writer):
            writer.get_extra_info('socket').setsockopt(socket.IPPROTO_TCP, socket.TCP_NODELAY, 1)
        await asyncio.gather(self._direction(client_reader, server_writer),
                             self._direction(server_reader, client_writer),
                             return_exceptions=True)
        for writer in (client_writer, server_writer):
            writer.close()

    async def _direction(self, reader, writer):
        loop = asyncio.get_running_loop()
        queue = asyncio.Queue(QUEUED_CHUNKS)

        async def read_side():
            while True:
                try:
                    data = await reader.read(CHUNK)
                except ConnectionError:
                    data = b''
                await queue.put((loop.time() + self.delay_ms / 1000.0, data))
                if not data:
                    return

        async def write_side():
            # FIFO: a chunk never overtakes an earlier one, even when the delay shrinks.
            while True:
                due, data = await queue.get()
                wait = due - loop.time()
                if wait > 0:
                    await asyncio.sleep(wait)
                if not data:
                    if writer.can_write_eof():
                        writer.write_eof()
                    return
                writer.write(data)
                await writer.drain()

        reading = asyncio.ensure_future(read_side())
        try:
            await write_side()
        except ConnectionError:
            writer.close()
        finally:
            reading.cancel()


def set_relay_delay(control_path, delay_ms, timeout=5.0):
    """Change the delay of a running relay; returns the delay it now applies (ms)."""
    return _control(control_path, 'delay %g\n' % delay_ms, timeout)


def get_relay_delay(control_path, timeout=5.0):
    return _control(control_path, 'get\n', timeout)


def _control(control_path, line, timeout):
    with socket.socket(socket.AF_UNIX, socket.SOCK_STREAM) as sock:
        sock.settimeout(timeout)
        sock.connect(control_path)
        sock.sendall(line.encode())
        reply = b''
        while not reply.endswith(b'\n'):
            part = sock.recv(256)
            if not part:
                break
            reply += part
    words = reply.decode().split(None, 1)
    if not words or words[0] != 'ok':
        raise RuntimeError('relay control: %s' % reply.decode().strip())
    return float(words[1])


async def _serve(args):
    relay = DelayRelay(split_host_port(args.listen), split_host_port(args.target),
                       args.delay_ms, args.control)
    check_bind_address(relay.listen[0])
    host, port = await relay.start()
    print('listening %s %d' % (host, port), flush=True)
    stop = asyncio.Event()
    loop = asyncio.get_running_loop()
    for signum in (signal.SIGTERM, signal.SIGINT):
        loop.add_signal_handler(signum, stop.set)
    await stop.wait()
    await relay.close()


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    parser.add_argument('--listen', required=True, help='ADDR:PORT (port 0: any free port)')
    parser.add_argument('--target', required=True, help='ADDR:PORT of the server')
    parser.add_argument('--delay-ms', type=float, default=0.0, help='one-way delay per direction')
    parser.add_argument('--control', help='path of a Unix socket to change the delay at run time')
    args = parser.parse_args(argv)
    try:
        asyncio.run(_serve(args))
    except ValueError as error:
        sys.exit('relay: %s' % error)


if __name__ == '__main__':
    main()
