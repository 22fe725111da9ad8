"""The campaign across hosts without hosts (rason_hosts.link_campaign): the plan drawn from a
seed, each run judged by its diagnosis and mission, and the report of drawn against clean links."""
import json
import os
import re

from rason_hosts.cli import play_and_judge
from rason_hosts.hosts import HostsError
from rason_hosts.link_campaign import (CLEAN, DELAYS_MS, FAULTS, HELP_TIMEOUT_S, LOSSES, MISSION_TOLERANCE,
                                       PARTITION_AFTER, PARTITION_SECONDS, by_factor, counted_apart, cut_band,
                                       draw_plan, goals, judge, link_label, missions, on_clean_link, remaining,
                                       report, save)
from rason_hosts.link_figures import links_figure, loss_columns

FAULTY_ASL = os.path.join(os.path.dirname(__file__), '..', 'agents', 'case_study', 'faulty_dialogue.asl')


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
    assert '![Missions completed' in text and (tmp_path / 'links.png').read_bytes()[:4] == b'\x89PNG'



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

def _run(run, link, loss, completed, outcome='correct', partition=None, diagnosis_s=30.0):
    scenario = {'run': run, 'seed': 1000 + run, 'fault': 'left_actuator', 'recovery': True, 'loss': loss,
                'delay_ms': 0, 'partition': partition}
    return {'scenario': scenario, 'link': link, 'diagnosis_s': diagnosis_s,
            'verdict': {'outcome': outcome, 'component': 'left_actuator', 'reason': None,
                        'mission_completed': completed}}


def test_the_help_timeout_is_faulty_s():
    with open(FAULTY_ASL) as f:
        assert re.search(r'^helpTimeout\((\d+)\)\.', f.read(), re.M).group(1) == str(HELP_TIMEOUT_S * 1000)


def test_a_cut_longer_than_the_help_timeout_is_counted_apart_and_cuts_fall_in_bands():
    short = {'seconds': 4.0, 'after': 1.0}
    long = {'seconds': HELP_TIMEOUT_S + 1.0, 'after': 1.0}
    assert not counted_apart(_run(1, 'drawn', 10, True, partition=short)['scenario'])
    assert counted_apart(_run(1, 'drawn', 10, True, partition=long)['scenario'])
    assert [cut_band(_run(1, 'drawn', 0, True, partition=p)['scenario'])
            for p in (None, short, {'seconds': 5.0, 'after': 0}, {'seconds': 9.9, 'after': 0}, long)] == [
        'no cut', 'cut up to 5 s', 'cut up to 5 s', 'cut over 5 s', 'cut over %d s' % HELP_TIMEOUT_S]
    records = [_run(1, 'drawn', 10, True), _run(2, 'drawn', 20, False), _run(3, 'drawn', 30, False, partition=long)]
    assert missions(records) == (1, 2, 1)


def test_the_goals_say_the_share_completed_and_the_wrong_diagnoses_and_whether_they_are_met():
    met = [_run(k, 'drawn', 10, True) for k in range(1, 21)] + [_run(21, 'drawn', 10, False)]
    text = '\n'.join(goals(met))
    assert '**20 of 21 (95 %)**; goal at least 95 %: met.' in text
    assert 'Counted apart' in text and ': 0.' in text
    assert 'Wrong diagnoses, both links: **0**; goal 0: met.' in text
    missed = met + [_run(22, 'drawn', 30, False, outcome='wrong'), _run(22, 'clean', 0, True)]
    text = '\n'.join(goals(missed))
    assert '**20 of 22 (91 %)**; goal at least 95 %: not met.' in text
    assert '**1**; goal 0: not met.' in text


def test_each_factor_level_of_the_drawn_links_is_set_beside_its_clean_twins():
    records = [_run(1, 'drawn', 30, False), _run(1, 'clean', 0, True),
               _run(2, 'drawn', 10, True, partition={'seconds': 7.0, 'after': 1.0}), _run(2, 'clean', 0, True),
               _run(3, 'drawn', 30, True), _run(3, 'clean', 0, False)]
    rows = {(factor, level): (len(runs), missions(runs)[:2], missions(twins)[:2])
            for factor, level, runs, twins in by_factor(records)}
    assert rows[('loss', '10 %')] == (1, (1, 1), (1, 1))
    assert rows[('loss', '30 %')] == (2, (1, 2), (1, 2))
    assert rows[('cut', 'cut over 5 s')] == (1, (1, 1), (1, 1))
    assert rows[('cut', 'no cut')] == (2, (1, 2), (1, 2))
    assert [level for factor, level, _, _ in by_factor(records) if factor == 'loss'] == ['10 %', '30 %']
    text = report(records, 'Test')
    assert '| loss | 30 % | 2 | 2 | 0 | 0 | 1 of 2 | 1 of 2 |' in text


def test_the_figure_has_a_column_per_loss_level_with_the_runs_behind_it(tmp_path):
    records = [_run(1, 'drawn', 30, False, diagnosis_s=40.0), _run(1, 'clean', 0, True, diagnosis_s=20.0),
               _run(2, 'drawn', 0, True, partition={'seconds': 3.0, 'after': 1.0}, diagnosis_s=35.0),
               _run(2, 'clean', 0, True, diagnosis_s=21.0),
               _run(3, 'drawn', 30, True, outcome='undiagnosed'), _run(3, 'clean', 0, True, diagnosis_s=22.0)]
    columns = loss_columns(records)
    assert [(c[0], c[1], c[2]) for c in columns] == [('0 %', (1, 1), (1, 1)), ('30 %', (1, 2), (2, 2))]
    assert columns[0][3] == [(35.0, True)] and columns[1][3] == [(40.0, False)]
    assert sorted(columns[1][4]) == [20.0, 22.0]
    path = tmp_path / 'links.png'
    links_figure(records, str(path))
    assert path.read_bytes()[:4] == b'\x89PNG' and path.stat().st_size > 5000
