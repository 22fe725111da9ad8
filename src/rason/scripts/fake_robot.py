#!/usr/bin/python3
from rason_tools.fake_robot import main
main()
