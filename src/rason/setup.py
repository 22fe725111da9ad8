from setuptools import setup
from catkin_pkg.python_setup import generate_distutils_setup

setup(**generate_distutils_setup(packages=['rason_budget', 'rason_campaign', 'rason_hosts', 'rason_relay', 'rason_simlink', 'rason_tools'], package_dir={'': 'src'}))
