"""Headless Chromium (Debian's chromium and chromium-driver) driven by Selenium, for the
dashboard's browser tests; flags that keep it off the network and out of the way."""
import tempfile

from selenium import webdriver
from selenium.webdriver.chrome.service import Service
from selenium.webdriver.support.ui import WebDriverWait

CHROMIUM = '/usr/bin/chromium'
CHROMEDRIVER = '/usr/bin/chromedriver'
FLAGS = ['--headless=new', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
         '--disable-background-networking', '--disable-component-update', '--disable-sync',
         '--disable-dev-shm-usage', '--window-size=1600,1200']


def chromium():
    options = webdriver.ChromeOptions()
    options.binary_location = CHROMIUM
    for flag in FLAGS:
        options.add_argument(flag)
    options.add_argument('--user-data-dir=' + tempfile.mkdtemp(prefix='rason_chromium_'))
    return webdriver.Chrome(service=Service(CHROMEDRIVER), options=options)


def texts(driver, css):
    """The rendered text of every element matching css (an SVG element's text content), read
    in one go (the page redraws whole parts, so elements found one call earlier may be gone)."""
    return driver.execute_script(
        'return Array.from(document.querySelectorAll(arguments[0])).map(e => (e.innerText ?? e.textContent).trim());',
        css)


def attributes(driver, css, name):
    """The attribute name of every element matching css, read in one go."""
    return driver.execute_script(
        'return Array.from(document.querySelectorAll(arguments[0])).map(e => e.getAttribute(arguments[1]));',
        css, name)


def wait_until(driver, condition, timeout=20.0):
    """condition(driver) true within timeout; the last value, or raises TimeoutException."""
    return WebDriverWait(driver, timeout, poll_frequency=0.1).until(condition)


def set_slider(driver, fraction):
    """Moves the replay's time slider to fraction (0: the bag's start, 1: its end) as a user would."""
    driver.execute_script(
        "const s = document.getElementById('slider'); s.value = s.max * arguments[0];"
        "s.dispatchEvent(new Event('input'));", fraction)
