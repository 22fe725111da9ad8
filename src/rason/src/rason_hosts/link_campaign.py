"""A campaign of the case study across hosts with the link as a factor: each drawn scenario
(a fault, loss and delay on the robots' links, maybe a partition of Helper's link at a drawn
time and length) is run twice with the same seed, once on its drawn link and once on a clean
one, and judged by Faulty's diagnosis and, with the fault-tolerance mission, by the
simulator's true poses. The report sets the two links side by side.

Pure: drawing the plan, judging a run and writing the report. ``rosrun rason hosts campaign``
(cli.py) plays it with CaseStudyOnHosts.
"""
import json
import random
import statistics

FAULTS = ('none', 'left_actuator', 'right_actuator', 'both_actuators', 'odometry')
LOSSES = (0, 10, 20, 30)            # % of frames lost each way on each robot's link
DELAYS_MS = (0, 50, 100, 200)       # ms added each way to each robot's connection to the broker
PARTITION_CHANCE = 0.5
PARTITION_SECONDS = (1.0, 10.0)     # how long Helper's link is cut
PARTITION_AFTER = (0.0, 6.0)        # s after Helper's search began
MISSION_TOLERANCE = 0.15            # m: the mission's judge (as the fault-tolerance rostests')
CLEAN = {'loss': 0, 'delay_ms': 0, 'partition': None}
HELP_TIMEOUT_S = 120                # Faulty's helpTimeout (faulty_dialogue.asl): a cut longer than this
                                    # ends the mission by design; such runs are counted apart
MISSION_GOAL = 0.95                 # missions completed on drawn links, of those counted
CUT_BANDS = (('no cut', 0), ('cut up to 5 s', 5), ('cut over 5 s', HELP_TIMEOUT_S))   # name, up to s


def draw_plan(runs, seed, faults=FAULTS, recovery=False):
    """runs scenarios: each a dict with run, seed (the simulator's), fault, recovery and its
    link (loss, delay_ms, partition: None or {'seconds', 'after'}). Faults in turn, so each
    gets its share; the link drawn from seed, never clean."""
    rng = random.Random(seed)
    plan = []
    for k in range(runs):
        partition = None
        if rng.random() < PARTITION_CHANCE:
            partition = {'seconds': round(rng.uniform(*PARTITION_SECONDS), 1),
                         'after': round(rng.uniform(*PARTITION_AFTER), 1)}
        loss, delay_ms = rng.choice(LOSSES), rng.choice(DELAYS_MS)
        if not (loss or delay_ms or partition):
            loss = rng.choice([p for p in LOSSES if p])     # a drawn link is never the clean one
        plan.append({'run': k + 1, 'seed': seed * 1000 + k + 1, 'fault': faults[k % len(faults)],
                     'recovery': recovery, 'loss': loss, 'delay_ms': delay_ms, 'partition': partition})
    return plan


def remaining(plan, records):
    """The records of the scenarios of plan played on both links, and the scenarios still to
    play (a scenario played on one link only is played again on both)."""
    links = {}
    for r in records:
        links.setdefault(r['scenario']['run'], []).append(r)
    done = [r for s in plan if len(links.get(s['run'], ())) == 2 for r in links[s['run']]]
    return done, [s for s in plan if len(links.get(s['run'], ())) != 2]


def on_clean_link(scenario):
    """The same scenario (fault, seed) on a clean link."""
    return dict(scenario, **CLEAN)


def judge(scenario, diagnosis=None, failure=None, mission=None, closest=None, back=None):
    """A run's verdict: 'correct' (the injected fault diagnosed), 'wrong' (another component),
    or 'undiagnosed' (Faulty concluded undiagnosed, with its reason, or the run failed:
    failure says why). With the mission: completed when Faulty reports it and the true poses of
    the robot(s) that completed it came within MISSION_TOLERANCE of the goal (closest) and,
    when Faulty completed it itself, Faulty's back to its start (back; None when delegated)."""
    verdict = {'outcome': 'undiagnosed', 'component': None, 'reason': failure}
    if diagnosis is not None:
        component, evidence = diagnosis
        verdict['component'] = component
        if component == 'undiagnosed':
            verdict['reason'] = evidence
        else:
            verdict['outcome'] = 'correct' if component == scenario['fault'] else 'wrong'
    if scenario.get('recovery'):
        verdict['mission_completed'] = bool(
            mission and mission[0] == 'true' and closest is not None and closest <= MISSION_TOLERANCE
            and (back is None or back <= MISSION_TOLERANCE))
        verdict['closest'], verdict['back'] = closest, back
    return verdict


def link_label(scenario):
    """How the link of a scenario reads in the report: 'clean', or e.g. '20 % loss, 100 ms,
    cut 4.2 s at +1.5 s'."""
    parts = []
    if scenario['loss']:
        parts.append('%g %% loss' % scenario['loss'])
    if scenario['delay_ms']:
        parts.append('%d ms' % scenario['delay_ms'])
    if scenario['partition']:
        parts.append('cut %.1f s at +%.1f s' % (scenario['partition']['seconds'], scenario['partition']['after']))
    return ', '.join(parts) or 'clean'


def counted_apart(scenario):
    """A scenario whose cut outlasts the mission's own timeout: not counted for the goal."""
    return bool(scenario['partition']) and scenario['partition']['seconds'] > HELP_TIMEOUT_S


def cut_band(scenario):
    """The CUT_BANDS name of a scenario's partition."""
    seconds = scenario['partition']['seconds'] if scenario['partition'] else 0
    for name, upto in CUT_BANDS:
        if seconds <= upto:
            return name
    return 'cut over %d s' % HELP_TIMEOUT_S


FACTORS = (('loss', lambda s: '%g %%' % s['loss']), ('delay', lambda s: '%d ms' % s['delay_ms']),
           ('cut', cut_band), ('fault', lambda s: s['fault']))


def missions(records):
    """(completed, counted, apart): missions completed among the runs counted, and the number
    counted apart (counted_apart). Runs without the mission count for nothing."""
    with_mission = [r for r in records if 'mission_completed' in r['verdict']]
    apart = [r for r in with_mission if counted_apart(r['scenario'])]
    counted = [r for r in with_mission if not counted_apart(r['scenario'])]
    return sum(r['verdict']['mission_completed'] for r in counted), len(counted), len(apart)


def goals(records):
    """The acceptance goals of the campaign, measured on the drawn links: lines of Markdown."""
    drawn = [r for r in records if r['link'] == 'drawn']
    wrong = sum(1 for r in records if r['verdict']['outcome'] == 'wrong')
    lines = []
    completed, counted, apart = missions(drawn)
    if counted:
        share = completed / counted
        lines.append('- Missions completed on the drawn links: **%d of %d (%.0f %%)**; goal at least %.0f %%: %s.'
                     % (completed, counted, 100 * share, 100 * MISSION_GOAL,
                        'met' if share >= MISSION_GOAL else 'not met'))
        lines.append('- Counted apart (a cut longer than Faulty\'s %d s help timeout): %d.' % (HELP_TIMEOUT_S, apart))
    lines.append('- Wrong diagnoses, both links: **%d**; goal 0: %s.' % (wrong, 'met' if wrong == 0 else 'not met'))
    return lines


def by_factor(records):
    """(factor, level, drawn records, their clean twins) for every level of every factor the
    drawn links took, in FACTORS order and levels in the order drawn values sort."""
    drawn = [r for r in records if r['link'] == 'drawn']
    clean = {r['scenario']['run']: r for r in records if r['link'] == 'clean'}
    rows = []
    for factor, level_of in FACTORS:
        levels = {}
        for r in drawn:
            levels.setdefault(level_of(r['scenario']), []).append(r)
        for level in sorted(levels, key=lambda k: _level_key(factor, k)):
            runs = levels[level]
            twins = [clean[r['scenario']['run']] for r in runs if r['scenario']['run'] in clean]
            rows.append((factor, level, runs, twins))
    return rows


def _level_key(factor, level):
    if factor in ('loss', 'delay'):
        return float(level.split()[0])
    if factor == 'cut':
        names = [name for name, _ in CUT_BANDS]
        return names.index(level) if level in names else len(names)
    return FAULTS.index(level) if level in FAULTS else 99


def _missions_cell(records):
    completed, counted, _ = missions(records)
    return '%d of %d' % (completed, counted) if counted else '-'


def _factor_table(records):
    rows = []
    for factor, level, runs, twins in by_factor(records):
        count = lambda outcome: sum(1 for r in runs if r['verdict']['outcome'] == outcome)  # noqa: E731
        rows.append([factor, level, str(len(runs)), str(count('correct')), str(count('undiagnosed')),
                     str(count('wrong')), _missions_cell(runs), _missions_cell(twins)])
    return _table(['factor', 'level', 'drawn runs', 'correct', 'undiagnosed', 'wrong',
                   'missions completed, drawn', 'the same runs, clean'], rows)


def _summary_row(name, records):
    n = len(records)
    count = lambda outcome: sum(1 for r in records if r['verdict']['outcome'] == outcome)  # noqa: E731
    times = [r['diagnosis_s'] for r in records if r['verdict']['outcome'] == 'correct' and r.get('diagnosis_s')]
    row = [name, str(n), str(count('correct')), str(count('undiagnosed')), str(count('wrong'))]
    missions = [r['verdict']['mission_completed'] for r in records if 'mission_completed' in r['verdict']]
    row.append('%d of %d' % (sum(missions), len(missions)) if missions else '-')
    row.append('%.1f / %.1f' % (statistics.median(times), max(times)) if times else '-')
    return row


def _table(header, rows):
    lines = ['| ' + ' | '.join(header) + ' |', '|' + '---|' * len(header)]
    lines += ['| ' + ' | '.join(row) + ' |' for row in rows]
    return '\n'.join(lines)


def report(records, title, how='', figure=None):
    """The campaign's report in Markdown: records are dicts with scenario, link ('drawn' or
    'clean'), verdict and diagnosis_s (wall s from launch to the diagnosis); how: a paragraph
    on how it was made (command, date, machine); figure: the file name of its figure."""
    drawn = [r for r in records if r['link'] == 'drawn']
    clean = [r for r in records if r['link'] == 'clean']
    header = ['link', 'runs', 'correct', 'undiagnosed', 'wrong', 'missions completed',
              'time to diagnosis (correct runs) median / max, s']
    summary = _table(header, [_summary_row('drawn (lossy, slow, cut)', drawn), _summary_row('clean', clean)])
    out = ['# ' + title, ''] + ([how, ''] if how else []) + [summary, ''] + goals(records) + ['']
    if figure:
        out += ['![Missions completed and time to diagnosis by loss, drawn links beside the same runs on '
                'a clean link](%s)' % figure, '']
    out += ['By factor of the drawn link (each run beside its clean twin):', '', _factor_table(records), '']
    reasons = {}
    for r in records:
        if r['verdict']['outcome'] == 'undiagnosed':
            reasons.setdefault(r['verdict']['reason'] or 'no reason given', []).append(
                '%d %s' % (r['scenario']['run'], r['link']))
    if reasons:
        out += ['Undiagnosed, by reason:', '']
        out += ['- %s: runs %s' % (reason, ', '.join(runs)) for reason, runs in sorted(reasons.items())]
        out.append('')
    rows = []
    for r in sorted(records, key=lambda r: (r['scenario']['run'], r['link'] != 'drawn')):
        s, v = r['scenario'], r['verdict']
        mission = '-' if 'mission_completed' not in v else ('yes' if v['mission_completed'] else 'no')
        rows.append([str(s['run']), str(s['seed']), s['fault'], link_label(s), v['outcome'],
                     v['component'] or '-', mission,
                     '%.1f' % r['diagnosis_s'] if r.get('diagnosis_s') else '-'])
    out += ['Every run:', '', _table(['run', 'seed', 'fault', 'link', 'outcome', 'diagnosed', 'mission',
                                      'diagnosis after, s'], rows), '']
    return '\n'.join(out)


def save(records, path):
    with open(path, 'w') as f:
        json.dump(records, f, indent=1, sort_keys=True)
