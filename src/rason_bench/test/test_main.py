"""run_bench's options."""
import pytest

from rason_bench import main


def test_every_part_runs_by_default_and_preemption_can_run_alone():
    assert set(main.PARTS) == {'startup', 'cycle', 'latency', 'cpu', 'reaction', 'scale', 'preemption', 'hostile', 'fleet',
                               'behaviour', 'budget', 'fleet_sim'}
    # behaviour and fleet_sim start the simulator on the bench's master and set /use_sim_time;
    # budget's case-study runs have masters of their own
    assert main.PARTS[-3:] == ('behaviour', 'budget', 'fleet_sim')
    assert main._parse(['--only', 'fleet_sim']).only == ['fleet_sim']
    assert main._parse(['--only', 'preemption']).only == ['preemption']
    assert main._parse([]).only is None


def test_take_backs_option():
    assert main._parse([]).take_backs is None
    assert main._parse(['--take-backs', '30']).take_backs == 30
    with pytest.raises(SystemExit):
        main._parse(['--only', 'preempt'])


def test_control_rate_is_the_goals_50_hz():
    assert main.CONTROL_RATE_HZ == 50.0


def test_hostile_can_run_alone_and_its_flood_is_the_issues():
    assert main._parse(['--only', 'hostile']).only == ['hostile']
    assert (main.FLOOD_SECONDS, main.FLOOD_RATE_HZ, main.FLOOD_LITERALS) == (20.0, 1000.0, 50)


def test_fleet_can_run_alone_among_the_issues_100_robots_at_10_and_20_percent_loss():
    assert main._parse(['--only', 'fleet']).only == ['fleet']
    assert (main.FLEET_ROBOTS, main.FLEET_LOSSES) == (100, (10, 20))
    assert set(main.FLEET) == set(main.FLEET_QUICK)
    assert main.FLEET_QUICK['loss_window_s'] < main.FLEET['loss_window_s']
