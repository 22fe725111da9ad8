#!/usr/bin/python3
"""The dashboard in headless Chromium during a case-study run: three robots' agents side by
side (faulty, helper and a third robot), a belief, an intention, the dialogue and the
diagnosis, the two simulated robots on the map and Faulty's call as arrows of the sequence
diagram; then the run's bag, replayed in the dashboard, shows the same dialogue, diagnosis and
robots on the map as the live page did."""
import os
import sys
import time
import unittest

import rosnode
import rason_rospy
import rospy
import rostest

import rospkg
sys.path.insert(0, os.path.join(rospkg.RosPack().get_path('rason_dashboard'), 'test'))
from browser import attributes, chromium, set_slider, texts, wait_until  # noqa: E402
from rason_dashboard.replay import load_bag  # noqa: E402
from rason_dashboard.server import DashboardServer  # noqa: E402

RUN = 180.0  # s (wall) for the whole case study at rate 2


def plans(view, agent):
    """The plans of agent's intentions in a dashboard view."""
    return [plan for robot in view['robots'] for a in robot['agents'] if a['name'] == agent
            for intention in a['intentions'] for plan in intention['plans']]


def first_time(timeline, condition, step=0.1):
    """The first time (s, step apart) at which condition(view) holds, or None."""
    first, last = timeline.span()
    for k in range(int((last - first) / step) + 1):
        t = first + k * step
        if condition(timeline.view(t)):
            return t
    return None


def dialogue(driver):
    """The page's messages between robots, without their times."""
    return attributes(driver, '.dialogue', 'data-line')


def map_robots(driver):
    """The robots on the page's map, each with its true and its believed pose drawn or not."""
    return driver.execute_script(
        "return Array.from(document.querySelectorAll('svg.map .robot-mark')).map(g => "
        "[g.dataset.mapRobot, !!g.querySelector('.true'), !!g.querySelector('.believed')]).sort();")


def arrows(driver):
    """(sender, receiver, step) of the sequence diagram's arrows."""
    return [tuple(a) for a in driver.execute_script(
        "return Array.from(document.querySelectorAll('svg.sequence .msg .arrow')).map("
        "a => [a.closest('.msg').dataset.from, a.dataset.to, a.closest('.msg').dataset.step]);")]


class TestDashboardLive(unittest.TestCase):

    def test_live_then_replayed(self):
        rason_rospy.init_node('test_dashboard_live')
        started = time.time()
        deadline = time.monotonic() + 30
        while not rospy.has_param('/dashboard/url'):
            self.assertLess(time.monotonic(), deadline, 'the dashboard did not start')
            time.sleep(0.1)
        url = rospy.get_param('/dashboard/url')
        self.assertTrue(url.startswith('http://127.0.0.1:'), url)
        driver = chromium()
        self.addCleanup(driver.quit)
        driver.get(url)

        wait_until(driver, lambda d: sorted(attributes(d, '[data-agent]', 'data-agent'))
                   == ['faulty', 'helper', 'third_courier'], timeout=60)
        self.assertEqual(sorted(attributes(driver, '[data-robot]', 'data-robot')),
                         ['/faulty/rason_mas', '/helper/rason_mas', '/third/rason_mas'])
        self.assertIn('charge(90)[source(self)]', texts(driver, '[data-agent=third_courier] .belief'))
        # the simulator's two robots on the map, true pose and odometry; the third has no body
        wait_until(driver, lambda d: map_robots(d) == [['faulty', True, True], ['helper', True, True]], timeout=30)
        # an intention that lasts (the helper's come and go in seconds; they are checked in the replay)
        wait_until(driver, lambda d: any('awaitParcel' in p for p in texts(d, '[data-agent=third_courier] .plan')),
                   timeout=30)
        # the diagnosis_reporter's words: "faulty: fault in both actuators (evidence)"
        wait_until(driver, lambda d: 'fault in both actuators' in ' '.join(texts(d, '[data-status="rason/diagnosis"]')),
                   timeout=RUN)
        wait_until(driver, lambda d: 'faulty -> helper: achieve thanks' in dialogue(d), timeout=30)
        live_dialogue = dialogue(driver)
        live_diagnosis = texts(driver, '[data-status="rason/diagnosis"]')
        self.assertIn('faulty -> all: achieve helpme', live_dialogue)
        live_arrows = arrows(driver)  # the broadcast: an arrow to every other agent's lane
        self.assertIn(('faulty', 'helper', 'call'), live_arrows)
        self.assertIn(('faulty', 'third_courier', 'call'), live_arrows)
        self.assertIn(('helper', 'faulty', 'accept'), live_arrows)

        # the bag: closed when its recorder stops
        bag = rospy.get_param('~bag')
        rosnode.kill_nodes(['/recorder'])
        deadline = time.monotonic() + 30
        while not (os.path.exists(bag) and os.path.getmtime(bag) >= started):
            self.assertLess(time.monotonic(), deadline, 'the recorder did not close %s' % bag)
            time.sleep(0.2)
        timeline, counts = load_bag(bag)
        self.assertGreater(counts['minds'], 0, 'no jason/mind in the bag')
        server = DashboardServer(timeline, '127.0.0.1', 0).start()
        self.addCleanup(server.stop)
        driver.get(server.url)
        wait_until(driver, lambda d: d.find_element('id', 'slider').is_displayed())
        wait_until(driver, lambda d: texts(d, '[data-status="rason/diagnosis"]') == live_diagnosis)
        # the same lines; two sent by different robots milliseconds apart (the helper's
        # feedback, Faulty's thanks) may reach the recorder and the dashboard in either order
        self.assertCountEqual(dialogue(driver), live_dialogue)
        self.assertEqual(map_robots(driver), [['faulty', True, True], ['helper', True, True]])
        # back to when the helper searched for Faulty: its plan is on the page
        searching = first_time(timeline, lambda view: any(
            'findRobot' in plan for plan in plans(view, 'helper')))
        self.assertIsNotNone(searching, 'no findRobot intention of the helper in the bag')
        first, last = timeline.span()
        set_slider(driver, (searching - first) / (last - first) + 0.001)
        wait_until(driver, lambda d: any('findRobot' in p for p in texts(d, '[data-agent=helper] .plan')))
        self.assertNotEqual(texts(driver, '[data-status="rason/diagnosis"]'), live_diagnosis)


if __name__ == '__main__':
    rostest.rosrun('rason', 'dashboard_live', TestDashboardLive)
