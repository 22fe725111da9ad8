"""The dashboard's web server (Python's own http.server): the page and its script from
web/, and the view of a Timeline with its pictures laid out as JSON at /api/view?t=SECONDS. Read-only: nothing a
browser sends reaches ROS or the agents."""
import json
import math
import os
import threading
from http.server import BaseHTTPRequestHandler, ThreadingHTTPServer
from urllib.parse import parse_qs, urlparse

from rason_dashboard.pictures import with_pictures

WEB = os.path.join(os.path.dirname(os.path.abspath(__file__)), 'web')
#: The files served, by path: nothing else of the disk is reachable.
FILES = {'/': ('index.html', 'text/html; charset=utf-8'),
         '/app.js': ('app.js', 'text/javascript; charset=utf-8'),
         '/fleet.js': ('fleet.js', 'text/javascript; charset=utf-8'),
         '/style.css': ('style.css', 'text/css; charset=utf-8')}


class BadRequest(ValueError):
    pass


def parse_time(query):
    """The t of a query string as finite seconds, None when absent."""
    values = parse_qs(query).get('t')
    if not values:
        return None
    try:
        t = float(values[0])
    except ValueError:
        raise BadRequest('t must be a number of seconds, not %r' % values[0][:40])
    if not math.isfinite(t):
        raise BadRequest('t must be finite')
    return t


def make_handler(timeline, log=None):
    class Handler(BaseHTTPRequestHandler):
        server_version = 'rason_dashboard'

        def do_GET(self):
            url = urlparse(self.path)
            if url.path == '/api/view':
                try:
                    t = parse_time(url.query)
                except BadRequest as e:
                    return self._send(400, 'text/plain; charset=utf-8', str(e).encode())
                body = json.dumps(with_pictures(timeline.view(t))).encode()
                return self._send(200, 'application/json', body)
            if url.path in FILES:
                name, kind = FILES[url.path]
                with open(os.path.join(WEB, name), 'rb') as f:
                    return self._send(200, kind, f.read())
            self._send(404, 'text/plain; charset=utf-8', b'not found')

        def _send(self, code, kind, body):
            self.send_response(code)
            self.send_header('Content-Type', kind)
            self.send_header('Content-Length', str(len(body)))
            self.send_header('Cache-Control', 'no-store')
            self.end_headers()
            self.wfile.write(body)

        def log_message(self, fmt, *args):  # quiet: one line per request would flood rosout
            if log is not None and args and str(args[1] if len(args) > 1 else '').startswith(('4', '5')):
                log(fmt % args)

    return Handler


class DashboardServer(object):
    """Serves timeline on (bind, port) in a thread of its own; port 0 takes a free one."""

    def __init__(self, timeline, bind='127.0.0.1', port=0, log=None):
        self._httpd = ThreadingHTTPServer((bind, port), make_handler(timeline, log))
        self._httpd.daemon_threads = True
        self._thread = threading.Thread(target=self._httpd.serve_forever, name='dashboard_http', daemon=True)

    @property
    def url(self):
        host, port = self._httpd.server_address[:2]
        return 'http://%s:%d/' % (host, port)

    def start(self):
        self._thread.start()
        return self

    def wait(self):
        """Until the server stops."""
        self._thread.join()

    def stop(self):
        self._httpd.shutdown()
        self._httpd.server_close()
