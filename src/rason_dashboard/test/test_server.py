"""The dashboard's web server: the page, the view as JSON, bad requests (no ROS master)."""
import json
import urllib.error
import urllib.request

import pytest

from rason_dashboard.server import DashboardServer
from rason_dashboard.timeline import Timeline


@pytest.fixture
def served():
    timeline = Timeline('replay')
    timeline.add_message(1.0, {'sender': 'faulty', 'receiver': 'all', 'performative': 'achieve',
                               'content': 'helpme', 'sender_mas': '/faulty/rason_mas',
                               'line': 'faulty -> all: achieve helpme'})
    timeline.add_message(2.0, {'sender': 'helper', 'receiver': 'faulty', 'performative': 'tell',
                               'content': 'found(faulty)', 'sender_mas': '/helper/rason_mas',
                               'line': 'helper -> faulty: tell found(faulty)'})
    server = DashboardServer(timeline, '127.0.0.1', 0).start()
    yield server.url
    server.stop()


def get(url):
    with urllib.request.urlopen(url, timeout=5) as r:
        return r.status, r.headers['Content-Type'], r.read()


def test_serves_the_page_its_script_and_style(served):
    status, kind, body = get(served)
    assert status == 200 and kind.startswith('text/html') and b'app.js' in body
    assert get(served + 'app.js')[1].startswith('text/javascript')
    assert get(served + 'style.css')[1].startswith('text/css')


def test_bound_to_loopback_by_default(served):
    assert served.startswith('http://127.0.0.1:')


def test_view_now_and_at_a_time(served):
    now = json.loads(get(served + 'api/view')[2])
    assert [m['line'] for m in now['messages']][-1] == 'helper -> faulty: tell found(faulty)'
    then = json.loads(get(served + 'api/view?t=1.5')[2])
    assert [m['line'] for m in then['messages']] == ['faulty -> all: achieve helpme']


@pytest.mark.parametrize('query', ['t=soon', 't=nan', 't=inf'])
def test_a_bad_time_is_a_400_with_the_reason(served, query):
    with pytest.raises(urllib.error.HTTPError) as e:
        get(served + 'api/view?' + query)
    assert e.value.code == 400 and b't must be' in e.value.read()


@pytest.mark.parametrize('path', ['nothing', '../package.xml', '%2e%2e/setup.py', 'web/index.html'])
def test_nothing_else_is_served(served, path):
    with pytest.raises(urllib.error.HTTPError) as e:
        get(served + path)
    assert e.value.code == 404
