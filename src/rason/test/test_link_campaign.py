"""The campaign across hosts without hosts (rason_hosts.link_campaign): the plan drawn from a
seed, each run judged by its diagnosis and mission, and the report of drawn against clean links."""
import json

from rason_hosts.cli import play_and_judge
from rason_hosts.hosts import HostsError
from rason_hosts.link_campaign import (CLEAN, DELAYS_MS, FAULTS, LOSSES, MISSION_TOLERANCE, PARTITION_AFTER,
                                       PARTITION_SECONDS, draw_plan, judge, link_label, on_clean_link, remaining,
                                       report, save)


def test_the_plan_is_drawn_from_the_seed_with_every_fault_in_turn():
    plan = draw_plan(40, seed=3)
    assert plan == draw_plan(40, seed=3)
    assert plan != draw_plan(40, seed=4)
    assert [s['fault'] for s in plan[:10]] == list(FAULTS) * 2
    assert [s['seed'] for s in plan[:3]] == [3001, 3002, 3003]
    assert {s['loss'] for s in plan} == set(LOSSES)
    assert {s['delay_ms'] for s in plan} == set(DELAYS_MS)
    assert all(s['loss'] or s['delay_ms'] or s['partition'] for s in plan)
    cuts = [s['partition'] for s in plan if s['partition']]
    assert 0 < len(cuts) < len(plan)
    for cut in cuts:
        assert PARTITION_SECONDS[0] <= cut['seconds'] <= PARTITION_SECONDS[1]
        assert PARTITION_AFTER[0] <= cut['after'] <= PARTITION_AFTER[1]
    assert draw_plan(2, 1, faults=('odometry',), recovery=True)[1]['recovery'] is True


def test_the_clean_twin_keeps_the_fault_and_seed_and_clears_the_link():
    scenario = {'run': 2, 'seed': 1002, 'fault': 'odometry', 'recovery': False, 'loss': 20, 'delay_ms': 100,
                'partition': {'seconds': 5.0, 'after': 1.0}}
    twin = on_clean_link(scenario)
    assert twin == dict(scenario, **CLEAN)
    assert scenario['loss'] == 20      # the drawn scenario is untouched
    assert link_label(twin) == 'clean'
    assert link_label(scenario) == '20 % loss, 100 ms, cut 5.0 s at +1.0 s'


def test_a_run_is_correct_wrong_or_undiagnosed_with_its_reason():
    scenario = {'fault': 'left_actuator'}
    assert judge(scenario, ('left_actuator', 'seen turning'))['outcome'] == 'correct'
    assert judge(scenario, ('right_actuator', 'seen turning'))['outcome'] == 'wrong'
    verdict = judge(scenario, ('undiagnosed', 'no diagnosis within the help timeout'))
    assert (verdict['outcome'], verdict['reason']) == ('undiagnosed', 'no diagnosis within the help timeout')
    verdict = judge(scenario, failure="waited 240 s for Faulty's diagnosis in vain; last lines:")
    assert (verdict['outcome'], verdict['component']) == ('undiagnosed', None)
    assert 'mission_completed' not in verdict


def test_a_mission_is_completed_only_when_reported_and_seen_by_the_true_poses():
    scenario = {'fault': 'left_actuator', 'recovery': True}
    near = MISSION_TOLERANCE / 2
    done = ('true', 'faulty', 'compensate')
    assert judge(scenario, ('left_actuator', ''), mission=done, closest=near, back=near)['mission_completed']
    assert not judge(scenario, ('left_actuator', ''), mission=done, closest=2 * MISSION_TOLERANCE,
                     back=near)['mission_completed']
    assert not judge(scenario, ('left_actuator', ''), mission=('false', '', 'delegate'), closest=near,
                     back=near)['mission_completed']
    assert not judge(scenario, failure='timeout')['mission_completed']
    delegated = ('true', 'helper', 'delegate')
    assert judge(scenario, ('both_actuators', ''), mission=delegated, closest=near, back=None)['mission_completed']
    assert not judge(scenario, ('both_actuators', ''), mission=delegated, closest=None, back=None)['mission_completed']


def test_the_report_sets_drawn_and_clean_links_side_by_side(tmp_path):
    plan = draw_plan(2, seed=1, recovery=True)
    records = [
        {'scenario': plan[0], 'link': 'drawn', 'diagnosis_s': 30.0,
         'verdict': judge(plan[0], (plan[0]['fault'], ''), mission=('true', 'faulty', 'compensate'),
                          closest=0.05, back=0.05)},
        {'scenario': on_clean_link(plan[0]), 'link': 'clean', 'diagnosis_s': 20.0,
         'verdict': judge(plan[0], (plan[0]['fault'], ''), mission=('true', 'faulty', 'compensate'),
                          closest=0.05, back=0.05)},
        {'scenario': plan[1], 'link': 'drawn',
         'verdict': judge(plan[1], ('undiagnosed', 'no diagnosis within the help timeout'))},
        {'scenario': on_clean_link(plan[1]), 'link': 'clean', 'diagnosis_s': 22.0,
         'verdict': judge(plan[1], (plan[1]['fault'], ''), mission=('true', 'faulty', 'compensate'),
                          closest=0.05, back=0.3)},
    ]
    text = report(records, 'Test campaign')
    assert '| drawn (lossy, slow, cut) | 2 | 1 | 1 | 0 | 1 of 2 | 30.0 / 30.0 |' in text
    assert '| clean | 2 | 2 | 0 | 0 | 1 of 2 | 21.0 / 22.0 |' in text
    assert '- no diagnosis within the help timeout: runs 2 drawn' in text
    assert '| 2 | 1002 | %s | clean | correct | %s | no | 22.0 |' % (plan[1]['fault'], plan[1]['fault']) in text
    save(records, str(tmp_path / 'results.json'))
    assert json.loads((tmp_path / 'results.json').read_text())[2]['verdict']['outcome'] == 'undiagnosed'


def test_the_report_is_made_again_from_a_campaign_s_results(tmp_path):
    from rason_hosts.cli import main
    plan = draw_plan(1, seed=5)
    records = [{'scenario': plan[0], 'link': 'drawn', 'diagnosis_s': 31.0,
                'verdict': judge(plan[0], (plan[0]['fault'], ''))},
               {'scenario': on_clean_link(plan[0]), 'link': 'clean', 'diagnosis_s': 25.0,
                'verdict': judge(plan[0], ('right_actuator', ''))}]
    save(records, str(tmp_path / 'results.json'))
    (tmp_path / 'campaign.json').write_text(json.dumps({'command': 'rosrun rason hosts campaign --runs 1', 'seed': 5,
                                                        'started': '2026-11-27 01:00', 'rate': 0, 'cores': 2}))
    assert main(['campaign', '--analyze-only', '--out', str(tmp_path)]) == 1     # a wrong diagnosis
    text = (tmp_path / 'report.md').read_text()
    assert text.startswith('# The case study across hosts: 1 scenarios (seed 5)')
    assert 'Made by `rosrun rason hosts campaign --runs 1` from 2026-11-27 01:00 UTC' in text
    assert '| clean | 1 | 0 | 0 | 1 |' in text



class _RunEndingAfterItsDiagnosis:
    """A CaseStudyOnHosts whose run gave its diagnosis, then never ended its mission."""

    def __init__(self):
        self.marks = {'launched': 10.0}
        self.diagnosis = None

    def play(self):
        self.diagnosis, self.marks['diagnosis'] = ('odometry', 'seen moving'), 42.5
        raise HostsError("waited 400 s for the mission's end in vain; last lines:\n...")


def test_a_run_that_failed_after_its_diagnosis_keeps_it_and_says_why_the_mission_did_not_end():
    played = play_and_judge(_RunEndingAfterItsDiagnosis(), {'fault': 'odometry', 'recovery': True})
    verdict = played['verdict']
    assert (verdict['outcome'], verdict['component'], verdict['mission_completed']) == ('correct', 'odometry', False)
    assert verdict['reason'] == "waited 400 s for the mission's end in vain"
    assert played['diagnosis_s'] == 32.5


def test_a_resumed_campaign_plays_only_the_scenarios_not_played_on_both_links():
    plan = draw_plan(4, seed=7)
    played = lambda s, link: {'scenario': s if link == 'drawn' else on_clean_link(s), 'link': link,  # noqa: E731
                              'verdict': judge(s, (s['fault'], ''))}
    records = [played(plan[0], 'drawn'), played(plan[0], 'clean'), played(plan[1], 'drawn'),
               played(plan[2], 'clean'), played(plan[2], 'drawn')]
    done, to_play = remaining(plan, records)
    assert [(r['scenario']['run'], r['link']) for r in done] == [(1, 'drawn'), (1, 'clean'), (3, 'clean'), (3, 'drawn')]
    assert [s['run'] for s in to_play] == [2, 4]
    assert remaining(plan, []) == ([], plan)


def test_a_cut_is_timed_from_helper_s_search_or_with_no_fault_from_faulty_s_first_move():
    from rason_hosts.case_study import cut_anchor
    search, moving = '[helper] Finding faulty turning 10 degrees', '[faulty] Moving to Destination'
    diagnosis = '[faulty] Diagnosis: none (no fault)'
    assert cut_anchor('left_actuator').search(search) and not cut_anchor('left_actuator').search(moving)
    assert cut_anchor('none').search(moving) and not cut_anchor('none').search(search)
    assert all(cut_anchor(f).search(diagnosis) for f in ('none', 'odometry'))


def test_a_resumed_campaign_s_report_says_when_it_was_resumed(tmp_path):
    from rason_hosts.cli import main
    plan = draw_plan(1, seed=5)
    save([{'scenario': plan[0], 'link': 'drawn', 'verdict': judge(plan[0], (plan[0]['fault'], ''))},
          {'scenario': on_clean_link(plan[0]), 'link': 'clean', 'verdict': judge(plan[0], (plan[0]['fault'], ''))}],
         str(tmp_path / 'results.json'))
    (tmp_path / 'campaign.json').write_text(json.dumps({
        'command': 'rosrun rason hosts campaign --runs 1', 'seed': 5, 'started': '2026-11-27 01:00', 'rate': 0,
        'cores': 2, 'resumed': [{'at': '2026-11-27 02:00', 'from_run': 1, 'command': 'rosrun rason hosts campaign '
                                                                                    '--runs 1 --resume'}]}))
    assert main(['campaign', '--analyze-only', '--out', str(tmp_path)]) == 0
    assert 'Resumed from run 1 at 2026-11-27 02:00 UTC (`rosrun rason hosts campaign --runs 1 --resume`).' in \
        (tmp_path / 'report.md').read_text()
