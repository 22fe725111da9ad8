"""The dashboard in a real browser (headless Chromium) over a recorded bag: every robot's
agents, a belief, an intention, the dialogue and the diagnosis appear, and moving the time
slider changes the view (no ROS master: a replay publishes nothing)."""
import os
import sys

import pytest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from browser import attributes, chromium, set_slider, texts, wait_until  # noqa: E402
from dashboard_data import case_study_bag  # noqa: E402
from rason_dashboard.replay import load_bag  # noqa: E402
from rason_dashboard.server import DashboardServer  # noqa: E402


@pytest.fixture
def page(tmp_path):
    path = str(tmp_path / 'run.bag')
    case_study_bag(path)
    timeline, _ = load_bag(path)
    server = DashboardServer(timeline, '127.0.0.1', 0).start()
    driver = chromium()
    driver.get(server.url)
    yield driver
    driver.quit()
    server.stop()


def test_the_end_of_the_run_shows_robots_agents_dialogue_and_diagnosis(page):
    wait_until(page, lambda d: len(attributes(d, '[data-robot]', 'data-robot')) == 2)
    assert sorted(attributes(page, '[data-agent]', 'data-agent')) == ['faulty', 'helper']
    assert 'found(faulty)[source(self)]' in texts(page, '[data-agent=helper] .belief')
    assert attributes(page, '.dialogue', 'data-line')[-1] == 'helper -> faulty: tell found(faulty)'
    assert texts(page, '[data-status="rason/diagnosis"]') == ['rason/diagnosis: faulty: both_actuators']
    assert page.find_element('id', 'slider').is_displayed()
    assert attributes(page, '[data-robot="/faulty/rason_mas"] a.inspector', 'href') == ['http://127.0.0.1:40001']
    assert attributes(page, '[data-robot="/helper/rason_mas"] a.inspector', 'href') == []


def test_moving_the_slider_back_shows_the_search_and_forth_again_the_finding(page):
    wait_until(page, lambda d: d.find_element('id', 'slider').is_displayed())
    set_slider(page, 0.05)  # 0.45 s into the run: the helper searches, Faulty asked nobody yet
    wait_until(page, lambda d: texts(d, '[data-agent=helper] .belief') == ['searching[source(self)]'])
    assert texts(page, '[data-agent=helper] .plan') == ['p1: +!findRobot(faulty) <- turn(10)']
    assert texts(page, '[data-agent=helper] .action')[0].startswith('turn(10) (id 7')
    assert texts(page, '.dialogue') == [] and texts(page, '[data-status]') == []
    set_slider(page, 0.6)   # 5.4 s: found, one dialogue line each way
    wait_until(page, lambda d: texts(d, '[data-agent=helper] .belief') == ['found(faulty)[source(self)]'])
    assert len(texts(page, '.dialogue')) == 2
    assert texts(page, '[data-status]') == []
    set_slider(page, 1.0)
    wait_until(page, lambda d: len(texts(d, '[data-status]')) == 1)
