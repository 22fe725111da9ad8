"""The fleet's pictures in a real browser (headless Chromium) over a recorded fleet run of
four robots: the map with every robot's true and believed pose and who helps whom, the
contract net as a sequence diagram with a lane per agent, the intention stacks; moving the
slider changes them (no ROS master)."""
import os
import sys

import pytest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from browser import attributes, chromium, set_slider, texts, wait_until  # noqa: E402
from dashboard_data import FLEET_DIALOGUE, case_study_bag, fleet_bag  # noqa: E402
from rason_dashboard.replay import load_bag  # noqa: E402
from rason_dashboard.server import DashboardServer  # noqa: E402
from rason_dashboard.timeline import Timeline  # noqa: E402


def served(path):
    server = DashboardServer(load_bag(path)[0], '127.0.0.1', 0).start()
    driver = chromium()
    driver.get(server.url)
    wait_until(driver, lambda d: d.find_element('id', 'slider').is_displayed())
    return server, driver


@pytest.fixture
def fleet(tmp_path):
    path = str(tmp_path / 'fleet.bag')
    fleet_bag(path)
    server, driver = served(path)
    yield driver
    driver.quit()
    server.stop()


def arrows(driver):
    """(sender, receiver, step) of every arrow of the sequence diagram, top to bottom."""
    return [tuple(a) for a in driver.execute_script(
        "return Array.from(document.querySelectorAll('svg.sequence .msg .arrow')).map("
        "a => [a.closest('.msg').dataset.from, a.dataset.to, a.closest('.msg').dataset.step]);")]


def test_map_has_the_four_robots_and_the_diagram_the_contract_net(fleet):
    set_slider(fleet, 0.5)  # 5 s: r1 took the award and drives towards r4
    wait_until(fleet, lambda d: attributes(d, 'svg.map .help', 'data-helper') == ['r1'])
    assert attributes(fleet, 'svg.map .help', 'data-helped') == ['r4']
    assert sorted(attributes(fleet, 'svg.map .robot-mark', 'data-map-robot')) == ['r1', 'r2', 'r3', 'r4']
    # the pictures name nothing as the cards do: the cards' robots and agents are found as before
    assert attributes(fleet, '[data-robot]', 'data-robot') == ['/r%d/rason_mas' % k for k in range(1, 5)]
    assert attributes(fleet, '[data-agent]', 'data-agent') == ['r1', 'r2', 'r3', 'r4']
    assert len(texts(fleet, 'svg.map .robot-mark .true')) == 4
    assert len(fleet.find_elements('css selector', 'svg.map .robot-mark .believed circle')) == 4
    assert attributes(fleet, 'svg.sequence .lane', 'data-lane') == ['r1', 'r2', 'r3', 'r4']
    expected = [('r2', 'r1', 'call'), ('r2', 'r3', 'call'), ('r2', 'r4', 'call'),  # the broadcast: every lane
                ('r4', 'r1', 'call'), ('r4', 'r2', 'call'), ('r4', 'r3', 'call'),
                ('r1', 'r4', 'bid'), ('r2', 'r4', 'bid'), ('r3', 'r4', 'refuse'),
                ('r4', 'r1', 'award'), ('r1', 'r4', 'accept')]
    assert arrows(fleet) == expected
    assert texts(fleet, 'svg.sequence .step-accept .label') == ['tell accepted(contract(r4,1))']
    assert texts(fleet, '#helps li') == ['r1 helps r4 (accepted(contract(r4,1)))']
    assert texts(fleet, '#stacks [data-stack-agent=r1] .frame') == \
        ['p7: +!carryOut(observe(r4),r4) <- goto(0,-1)', 'p6: +!work(Id,T,C) <- !carryOut(T,C)']


def test_the_slider_moves_the_robots_and_ends_the_help(fleet):
    def r1_x(d):
        return d.execute_script("const c = document.querySelector('svg.map [data-map-robot=r1] .true circle');"
                                "return c ? Number(c.getAttribute('cx')) : null;")
    set_slider(fleet, 0.2)  # 2 s: r4's call is out, no award yet
    wait_until(fleet, lambda d: len(arrows(d)) == 9)
    assert attributes(fleet, 'svg.map .help', 'data-helper') == []
    start = r1_x(fleet)
    set_slider(fleet, 1.0)  # the end: r1 moved 1 m towards the centre and was released
    wait_until(fleet, lambda d: len(arrows(d)) == len(FLEET_DIALOGUE) + 2)
    assert arrows(fleet)[-1] == ('r4', 'r1', 'end')
    assert attributes(fleet, 'svg.map .help', 'data-helper') == [] and texts(fleet, '#helps li') == []
    assert r1_x(fleet) < start


def test_the_case_studys_two_robots_without_poses(tmp_path):
    path = str(tmp_path / 'run.bag')
    case_study_bag(path)
    server, driver = served(path)
    try:
        wait_until(driver, lambda d: attributes(d, 'svg.sequence .lane', 'data-lane') == ['faulty', 'helper'])
        assert arrows(driver) == [('faulty', 'helper', 'call'), ('helper', 'faulty', 'accept')]
        assert texts(driver, '#map .empty') == ['no poses (/<robot>/true_pose, /<robot>/odom)']
        assert texts(driver, '#helps li') == ['helper helps faulty (found(faulty))']
    finally:
        driver.quit()
        server.stop()


def newest_row_in_sight(driver):
    return driver.execute_script(
        "const box = document.getElementById('sequence').getBoundingClientRect();"
        "const rows = document.querySelectorAll('svg.sequence .msg');"
        "if (!rows.length) return null;"
        "const last = rows[rows.length - 1].getBoundingClientRect();"
        "return [rows.length, last.top >= box.top && last.bottom <= box.bottom];")


def test_live_a_long_dialogue_keeps_its_newest_message_in_sight():
    timeline = Timeline('live')

    def say(i):
        timeline.add_message(float(i), {'sender': 'r%d' % (1 + i % 2), 'receiver': 'r%d' % (2 - i % 2),
                                        'performative': 'tell', 'content': 'n(%d)' % i, 'sender_mas': '',
                                        'line': 'n(%d)' % i})
    for i in range(40):  # more rows than the diagram's box shows
        say(i)
    server = DashboardServer(timeline, '127.0.0.1', 0).start()
    driver = chromium()
    try:
        driver.get(server.url)
        wait_until(driver, lambda d: newest_row_in_sight(d) == [40, True])
        say(40)  # the page polls: the new message comes into sight
        wait_until(driver, lambda d: newest_row_in_sight(d) == [41, True])
        assert driver.execute_script("return document.getElementById('sequence').scrollTop;") > 0
    finally:
        driver.quit()
        server.stop()
