#!/usr/bin/python3
"""The documentation's screenshots, taken with headless Chromium (the dashboard's browser
tests' driver) and saved as small palette PNGs:

  tools/screenshots.py dashboard BAG OUT.png [--at FRACTION] [--open-rules]
      the dashboard replaying BAG, its time slider at FRACTION of the run (0 start, 1 end)
  tools/screenshots.py fleet BAG OUT.png [--at FRACTION]
      writes the dashboard tests' four-robot fleet bag (a contract net, poses) to BAG, then as
      dashboard
  tools/screenshots.py page FILE.html OUT.png
      a page of the built docs site (make docs: build/site/...), opened from its file URL

Run with the ROS environment (the dashboard reads the bag with rosbag)."""
import argparse
import os
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, 'src', 'rason_dashboard', 'test'))
sys.path.insert(0, os.path.join(ROOT, 'src', 'rason_dashboard', 'src'))

COLOURS = 128  # a palette this size keeps text and the page's colours, at a fraction of the bytes


def save(driver, out, width, height):
    from PIL import Image
    driver.set_window_size(width, height)
    raw = out + '.raw.png'
    driver.save_screenshot(raw)
    Image.open(raw).convert('RGB').quantize(COLOURS).save(out, optimize=True)
    os.remove(raw)
    print('%s: %d bytes' % (out, os.path.getsize(out)))


def settled(driver, css):
    """Waits for css to be on the page, then for the page to stop redrawing."""
    from browser import wait_until
    wait_until(driver, lambda d: d.find_elements('css selector', css))
    time.sleep(0.5)  # a screenshot, not a test: the last redraw of the view just asked for


def dashboard(args):
    from browser import chromium, set_slider, wait_until
    from rason_dashboard.replay import load_bag
    from rason_dashboard.server import DashboardServer
    server = DashboardServer(load_bag(args.source)[0], '127.0.0.1', 0).start()
    driver = chromium()
    try:
        driver.get(server.url)
        wait_until(driver, lambda d: d.find_element('id', 'slider').is_displayed())
        set_slider(driver, args.at)
        settled(driver, '[data-agent]')
        if args.open_rules:
            for summary in driver.find_elements('css selector', '.rules summary'):
                summary.click()
        save(driver, args.out, args.width, args.height)
    finally:
        driver.quit()
        server.stop()


def fleet(args):
    from dashboard_data import fleet_bag
    fleet_bag(args.source)
    dashboard(args)


def page(args):
    from browser import chromium
    driver = chromium()
    try:
        driver.get('file://' + os.path.abspath(args.source))
        settled(driver, 'article')
        save(driver, args.out, args.width, args.height)
    finally:
        driver.quit()


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument('kind', choices=['dashboard', 'fleet', 'page'])
    p.add_argument('source', help='the bag (dashboard) or the .html file (page)')
    p.add_argument('out')
    p.add_argument('--at', type=float, default=1.0, help='dashboard: slider position, 0 to 1')
    p.add_argument('--open-rules', action='store_true', help='dashboard: expand the rules')
    p.add_argument('--width', type=int, default=1400)
    p.add_argument('--height', type=int, default=900)
    args = p.parse_args()
    {'dashboard': dashboard, 'fleet': fleet, 'page': page}[args.kind](args)


if __name__ == '__main__':
    main()
