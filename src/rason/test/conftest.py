# pytest (make unit) collects only the campaign's unit tests here: the other test_*.py
# scripts of this folder are rostest nodes that need a master.
import os

_here = os.path.dirname(os.path.abspath(__file__))
collect_ignore = [name for name in os.listdir(_here)
                  if name.endswith('.py') and name != 'conftest.py'
                  and not name.startswith('test_campaign_')]
