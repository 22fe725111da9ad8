# Rason: one-command set-up, tests, demo and benchmarks on Debian 12.
# ROS runs on Debian's /usr/bin/python3 (not a pyenv python3 first on PATH).
SHELL := /bin/bash
.DEFAULT_GOAL := help

PY := /usr/bin/python3
SUDO := $(shell [ "$$(id -u)" -eq 0 ] || echo sudo)
JAR := jason_lib/target/rason-jason-lib.jar
JAVA_SOURCES := $(shell find jason_lib/src/main -name '*.java' 2>/dev/null)

APT_PACKAGES := catkin ros-message-generation ros-message-runtime libstd-msgs-dev \
  python3-genpy python3-rospy python3-rosmaster python3-roslaunch rosout python3-rostest \
  python3-rosbag python3-rostopic python3-rosnode python3-rosservice python3-rosparam \
  python3-rosmsg python3-std-msgs python3-geometry-msgs python3-nav-msgs python3-sensor-msgs \
  python3-diagnostic-msgs python3-tf2-ros python3-cv-bridge python3-opencv python3-numpy \
  python3-pytest librostest-dev rosbash rospack-tools ros-sensor-msgs ros-nav-msgs \
  ros-diagnostic-msgs libsensor-msgs-dev libnav-msgs-dev libdiagnostic-msgs-dev \
  python3-jpype default-jdk-headless maven build-essential cmake \
  libroscpp-dev libgeometry-msgs-dev libros-rosgraph-msgs-dev libtf2-msgs-dev \
  libmujoco-dev libqhull-dev libosmesa6-dev libgtest-dev python3-matplotlib python3-psutil \
  python3-actionlib python3-actionlib-msgs ros-actionlib-msgs python3-std-srvs ros-std-srvs \
  python3-move-base-msgs ros-move-base-msgs \
  python3-selenium chromium chromium-driver python3-visualization-msgs ros-visualization-msgs python3-yaml \
  mosquitto mosquitto-clients python3-paho-mqtt nftables iproute2 \
  mkdocs mkdocs-material python3-pymdownx python3-pil

# Environment of every ROS command: the workspace's devel space, logs in build/.
export PYENV_VERSION := system
export ROS_HOME := $(CURDIR)/build/ros_home
export ROS_LOG_DIR := $(CURDIR)/build/ros_home/log
export ROS_IP := 127.0.0.1
ROSENV := set +u; source $(CURDIR)/devel/setup.bash; set -u;
# The fleet key of every rason_mas started through make (its default place under ROS_HOME).
FLEET_KEY := $(ROS_HOME)/rason/fleet.key

.PHONY: help setup apt jason_lib catkin test docs javatest unit rostest demo demo-hosts bench rate-check rviz clean

help:
	@echo "make demo   - set up, then run the case study (both actuators faulty) in the simulator"
	@echo "make demo-hosts - the same with each robot on a host of its own (network namespaces, MQTT, 20 % loss; root)"
	@echo "make test   - set up, then build the docs and run unit tests (JUnit, pytest) and rostests"
	@echo "make docs   - build the documentation site (docs/ -> build/site), failing on broken links"
	@echo "make setup  - install Debian packages, build jason_lib (Maven) and the catkin workspace, make a fleet key"
	@echo "make bench  - benchmarks (see docs/guides/benchmarks.md)"
	@echo "make rate-check - the case study at real-time factor 1 and 0: same diagnosis, steps within 10 %"
	@echo "make rviz   - install rviz if missing, then show the simulated world (run beside make demo)"

setup: apt jason_lib catkin $(FLEET_KEY)

# Idempotent: only asks apt when a package is missing.
apt:
	@missing=$$(dpkg-query -W -f='$${Package} $${Status}\n' $(APT_PACKAGES) 2>/dev/null \
	    | awk '$$NF=="installed"{print $$1}' | sort | comm -13 - <(tr ' ' '\n' <<<"$(APT_PACKAGES)" | grep . | sort)); \
	if [ -n "$$missing" ]; then \
	  echo "apt: installing $$missing"; \
	  $(SUDO) apt-get update -qq && \
	  DEBIAN_FRONTEND=noninteractive $(SUDO) apt-get install -y -qq $$missing; \
	else echo "apt: all packages present"; fi

# The jar, then the class-data sharing archive of rason_mas's JVM (remade only when the jars
# or Java changed; see docs/guides/robot-budget.md).
jason_lib: $(JAR)
	@PYTHONPATH=$(CURDIR)/src/rason_bridge/src $(PY) -m rason_bridge.cds_build $(CURDIR)
$(JAR): jason_lib/pom.xml $(JAVA_SOURCES)
	cd jason_lib && mvn -q -B package -DskipTests
	@touch $@

catkin:
	@catkin_make -DPYTHON_EXECUTABLE=$(PY) -DCMAKE_BUILD_TYPE=Release \
	  --cmake-args -Wno-dev > build.log 2>&1 || { tail -40 build.log; exit 1; }
	@echo "catkin: workspace built (log: build.log)"

# Made once (a random key, mode 0600), never overwritten: see docs/guides/security.md.
$(FLEET_KEY):
	@PYTHONPATH=$(CURDIR)/src/rason_bridge/src $(PY) -m rason_bridge.fleet_key $@

# The robots-on-hosts tests (network namespaces; root) mostly wait on shaped links and
# timeouts, so make test runs them beside everything else, with a log of their own, and
# waits for them at the end.
test: setup
	@$(MAKE) --no-print-directory docs && rm -rf build/test_results && \
	  { $(ROSENV) $(PY) -m rason_tools.lanes; status=$$?; \
	    $(ROSENV) $(PY) src/rason/test/summarize_results.py build/test_results && [ $$status = 0 ]; }

# The site under build/site, offline (no CDN, no web fonts); --strict fails on a missing page
# or include, check_site_links on a missing anchor.
docs: apt
	mkdocs build --strict --quiet
	$(PY) tools/check_site_links.py build/site

# JUnit (Surefire) for jason_lib, no ROS needed; prints Surefire's summary.
javatest:
	@mkdir -p build; cd jason_lib && mvn -B test > ../build/javatest.log 2>&1; status=$$?; \
	  grep -E "Tests run:|FAIL|ERROR\]" ../build/javatest.log | grep -v "^\[INFO\] *$$" | tail -40; exit $$status

# Every pytest test, one after the other (make test runs the hosts tests beside the rest).
unit:
	$(ROSENV) $(PY) -m pytest -q src

rostest:
	@rm -rf build/test_results; \
	  $(ROSENV) $(PY) -m rason_tools.lanes --only gtest,rostest; status=$$?; \
	  $(ROSENV) $(PY) src/rason/test/summarize_results.py build/test_results && [ $$status = 0 ]

demo: setup
	$(ROSENV) rosrun rason run_launch rason faulty_helper.launch fault:=both_actuators

# Faulty and Helper each with its own ROS master on a network host of its own, over MQTT on
# a lossy, slow link, one simulated world (docs/guides/hosts.md); needs root.
demo-hosts: setup
	$(ROSENV) rosrun rason hosts case-study --fault both_actuators --loss 20 --delay-ms 100

# The case study at real-time factor 1 and 0 (two campaign runs, about 40 s): same diagnosis,
# steps within 10 %. Part of make test too; this runs it alone.
rate-check: setup
	$(ROSENV) rostest rason rate_independence.test compare_steps:=true

# BENCH_ARGS: e.g. "--quick --seconds 1" for a smoke run (see src/rason_bench).
BENCH_ARGS ?=
bench: setup
	$(ROSENV) rosrun rason_bench run_bench --out $(CURDIR)/results/bench $(BENCH_ARGS)

# rviz is a viewer, not needed by demo or test: installed only when asked for.
rviz: setup
	@dpkg -s rviz >/dev/null 2>&1 || { $(SUDO) apt-get update -qq && \
	  DEBIAN_FRONTEND=noninteractive $(SUDO) apt-get install -y -qq rviz; }
	$(ROSENV) roslaunch rason rviz.launch

clean:
	rm -rf build devel jason_lib/target build.log
