"""summarize_results: counts rostest results and says why a test failed (CI keeps only the tail)."""
import os

import summarize_results

PASSED = ('<testsuite errors="0" failures="0" tests="1"><testcase name="test_ok"/>'
          '</testsuite>')
FAILED = ('<testsuite errors="0" failures="1" tests="1"><testcase name="test_diagnosis">'
          '<failure message="no diagnosis within 150 s">trace</failure></testcase></testsuite>')
LAUNCH = ('<testsuite errors="0" failures="0" tests="1"><testcase name="testx"/><system-out>'
          '[INFO] [1.0, 2.0]: [helper] Finding faulty turning 10 degrees\n'
          'plain line nobody needs\n'
          '[ERROR] [3.0]: bad callback\n</system-out></testsuite>')


def write(folder, name, text):
    os.makedirs(folder, exist_ok=True)
    with open(os.path.join(folder, name), 'w') as f:
        f.write(text)


def test_all_passed_exits_zero(tmp_path, capsys):
    write(str(tmp_path / 'rason'), 'rosunit-a.xml', PASSED)
    assert summarize_results.main(str(tmp_path)) == 0
    assert 'rostest: 1 passed, 0 failed' in capsys.readouterr().out


HELPER_LOG = (
    '[rospy.client][INFO] 2026-11-24 10:26:40,100: init_node, name[/helper/rason_mas]\n'
    '[rosout][INFO] 2026-11-24 10:26:48,070: [helper] Found faulty\n'
    '[rosout][INFO] 2026-11-24 10:26:48,100: presence: agent faulty is reachable\n'
    '[rosout][INFO] 2026-11-24 10:26:50,644: [helper] My view of faulty did not settle\n')
FAULTY_LOG = (
    '[rosout][INFO] 2026-11-24 10:26:48,146: [faulty] helper found me, asking to track me\n'
    '[rosout][WARNING] 2026-11-24 10:26:49,000: perceptions come faster than the agents take them\n')


def test_failure_prints_message_and_launch_tail(tmp_path, capsys):
    folder = str(tmp_path / 'rason')
    write(folder, 'rosunit-case_x.xml', FAILED)
    write(folder, 'rostest-test_case_x.xml', LAUNCH)
    assert summarize_results.main(str(tmp_path), str(tmp_path / 'no_logs')) == 1
    out = capsys.readouterr().out
    assert 'test_diagnosis: no diagnosis within 150 s' in out
    assert '[helper] Finding faulty' in out
    assert 'bad callback' in out
    assert 'plain line nobody needs' not in out
    # The one-line summary comes last, so a tail of the output still has it.
    assert out.rstrip().splitlines()[-1] == 'rostest: 1 passed, 1 failed'


def test_the_launch_tail_of_an_mqtt_variant_is_found_under_rostests_name_for_it(tmp_path, capsys):
    folder = str(tmp_path / 'rason')
    write(folder, 'rosunit-case_x_mqtt.xml', FAILED)
    write(folder, 'rostest-case_x__fleet_channel_mqtt.xml', LAUNCH)
    assert summarize_results.main(str(tmp_path), str(tmp_path / 'no_logs')) == 1
    assert '[helper] Finding faulty' in capsys.readouterr().out


def test_failure_prints_what_the_agents_of_its_run_printed_in_time_order(tmp_path, capsys):
    write(str(tmp_path / 'results' / 'rason'), 'rosunit-case_x.xml', FAILED)
    logs = tmp_path / 'log'
    older = str(logs / 'run-older')
    write(older, 'case_x-13.log', '')
    write(older, 'helper-rason_mas-7.log', '[rosout][INFO] 2026-11-24 09:00:00,000: [helper] old run\n')
    os.utime(os.path.join(older, 'case_x-13.log'), (1, 1))
    run = str(logs / 'run-newest')
    write(run, 'case_x-13.log', '')
    write(run, 'helper-rason_mas-7.log', HELPER_LOG)
    write(run, 'faulty-rason_mas-11.log', FAULTY_LOG)
    write(run, 'dialogue-12.log', '[rosout][INFO] 2026-11-24 10:26:49,500: an info line, not a print\n')
    assert summarize_results.main(str(tmp_path / 'results'), str(logs)) == 1
    out = capsys.readouterr().out
    lines = [l.strip() for l in out.splitlines()]
    tail = [l for l in lines if l.startswith('2026-')]
    assert tail == [
        '2026-11-24 10:26:48,070 INFO helper-rason_mas-7: [helper] Found faulty',
        '2026-11-24 10:26:48,146 INFO faulty-rason_mas-11: [faulty] helper found me, asking to track me',
        '2026-11-24 10:26:49,000 WARNING faulty-rason_mas-11: perceptions come faster than the agents '
        'take them',
        '2026-11-24 10:26:50,644 INFO helper-rason_mas-7: [helper] My view of faulty did not settle']
    assert 'run-newest' in out and 'old run' not in out


def test_run_folder_is_none_without_the_test_s_log(tmp_path):
    write(str(tmp_path / 'run'), 'other-1.log', '')
    assert summarize_results.run_folder(str(tmp_path), 'case_x') is None


def test_long_message_is_truncated(tmp_path, capsys):
    long_failure = FAILED.replace('no diagnosis within 150 s', 'x' * 5000)
    write(str(tmp_path / 'rason'), 'rosunit-b.xml', long_failure)
    summarize_results.main(str(tmp_path))
    out = capsys.readouterr().out
    assert 'more chars' in out and 'x' * 5000 not in out


def test_no_results_is_a_failure(tmp_path):
    assert summarize_results.main(str(tmp_path)) == 1


def test_unreadable_result_is_a_failure(tmp_path, capsys):
    write(str(tmp_path / 'rason'), 'rosunit-c.xml', '<testsuite')
    assert summarize_results.main(str(tmp_path)) == 1
    assert 'unreadable result' in capsys.readouterr().out
