"""An agent's mind made readable, in a real browser (headless Chromium): goals as !g, rules
apart from beliefs and collapsed, and what changed since the robot's step before marked, in a
replay and live (a live timeline fed here as the ROS node would; no ROS master)."""
import os
import sys

import pytest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from browser import chromium, set_slider, texts, wait_until  # noqa: E402
from dashboard_data import NEAR_RULE, case_study_bag  # noqa: E402
from rason_dashboard.replay import load_bag  # noqa: E402
from rason_dashboard.server import DashboardServer  # noqa: E402
from rason_dashboard.timeline import Timeline  # noqa: E402


def served(timeline):
    server = DashboardServer(timeline, '127.0.0.1', 0).start()
    driver = chromium()
    driver.get(server.url)
    return server, driver


@pytest.fixture
def replay(tmp_path):
    path = str(tmp_path / 'run.bag')
    case_study_bag(path)
    server, driver = served(load_bag(path)[0])
    wait_until(driver, lambda d: d.find_element('id', 'slider').is_displayed())
    yield driver
    driver.quit()
    server.stop()


def rules_open(driver):
    return driver.execute_script("return document.querySelector('[data-agent=helper] details.rules').open;")


def rule_shown(driver):
    return driver.execute_script("return document.querySelector('[data-agent=helper] .rule').checkVisibility();")


def test_goals_as_in_jason_and_rules_apart_collapsed(replay):
    set_slider(replay, 0.05)  # the helper searches for Faulty
    wait_until(replay, lambda d: texts(d, '[data-agent=helper] .goal') == ['!helpme[source(faulty)]'])
    assert NEAR_RULE not in texts(replay, '[data-agent=helper] .belief')
    assert [t.lower() for t in texts(replay, '[data-agent=helper] .rules summary')] == ['rules 1']
    assert not rules_open(replay) and not rule_shown(replay)
    replay.find_element('css selector', '[data-agent=helper] .rules summary').click()
    assert rules_open(replay) and rule_shown(replay) and texts(replay, '[data-agent=helper] .rule') == [NEAR_RULE]
    set_slider(replay, 0.6)  # the page redraws: the rules stay open
    wait_until(replay, lambda d: texts(d, '[data-agent=helper] .belief') == ['found(faulty)[source(self)]'])
    assert rules_open(replay) and rule_shown(replay)


def test_what_changed_since_the_step_before_is_marked(replay):
    set_slider(replay, 0.05)  # the helper's first snapshot: nothing to compare with
    wait_until(replay, lambda d: texts(d, '[data-agent=helper] .belief') == ['searching[source(self)]'])
    assert texts(replay, '.added') == [] and texts(replay, '.removed') == []
    set_slider(replay, 0.6)  # found Faulty: a belief replaced, the search's intention ended
    wait_until(replay, lambda d: texts(d, '[data-agent=helper] .belief.added') == ['found(faulty)[source(self)]'])
    assert texts(replay, '[data-agent=helper] [data-removed=belief]') == ['searching[source(self)]']
    assert texts(replay, '[data-agent=helper] [data-removed=goal]') == ['!helpme[source(faulty)]']
    assert texts(replay, '[data-agent=helper] [data-removed=intention]') == \
        ['#1 ended: p1: +!findRobot(faulty) <- turn(10)']
    assert texts(replay, '[data-agent=faulty] .added') == []  # Faulty did not change


def agent(beliefs, intentions):
    return {'mas_id': '/r', 'stamp': 0.0, 'agents': [{
        'name': 'rover', 'cycle': 1, 'stamp': 0.0, 'beliefs': beliefs, 'rules': [], 'goals': [],
        'intentions': intentions, 'actions': [], 'events': [], 'messages': [], 'omitted': 0}]}


def test_live_a_new_snapshot_marks_its_changes():
    timeline = Timeline('live')
    plan = ['+!go <- move(1)']
    timeline.add_mind(1.0, agent(['at(0)'], [{'id': 3, 'state': 'running', 'plans': plan}]))
    server, driver = served(timeline)
    try:
        wait_until(driver, lambda d: texts(d, '[data-agent=rover] .belief') == ['at(0)'])
        assert texts(driver, '.added') == [] and texts(driver, '.intention.changed') == []
        timeline.add_mind(2.0, agent(['at(1)'], [{'id': 3, 'state': 'waiting', 'plans': plan}]))
        wait_until(driver, lambda d: texts(d, '.belief.added') == ['at(1)'])  # the page polls: no reload
        assert texts(driver, '[data-removed=belief]') == ['at(0)']
        assert len(texts(driver, '.intention.changed')) == 1
    finally:
        driver.quit()
        server.stop()
