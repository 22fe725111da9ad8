"""The fleet_sim part's goal and Markdown (pure: the ``fleet_sim`` dict of results.json in,
text out)."""

#: Issue 34: the simulator with six robots (three cameras), lockstep on, at least real time.
RTF_GOAL, RTF_GOAL_ROBOTS = 1.0, 6


def _size(fleet_sim, n):
    return next((s for s in fleet_sim.get('sizes', []) if s['robots'] == n), None)


def goals(fleet_sim):
    """[(goal, measured, met)] of the fleet_sim part (none if it did not run)."""
    if not fleet_sim:
        return []
    s = _size(fleet_sim, RTF_GOAL_ROBOTS)
    goal = ('simulator with %d robots (3 cameras), every execution layer, lockstep on (rate 0): '
            'real-time factor >= %g' % (RTF_GOAL_ROBOTS, RTF_GOAL))
    if s is None or s['real_time_factor'] is None:
        return [(goal, 'not measured', False)]
    rtf = s['real_time_factor']
    return [(goal, '%.2f' % rtf, rtf >= RTF_GOAL)]


def _row(cells):
    return '| ' + ' | '.join(cells) + ' |'


def text(fleet_sim):
    """The part's table: one row per fleet size."""
    out = ['`fleet.launch robots:=r1 ... rN rate:=0` (lockstep on; max_lockstep_factor 2.5 is the '
           'ceiling), every robot turning in place on its decomposer; measured over %g wall s. CPU in %% '
           'of one core: the simulator process, every process of the launch (simulator, decomposers, '
           'fault injectors, diagnosis reporters, vision_synth, roslaunch), and the whole machine '
           '(other work on it included). Frames: each camera robot\'s robots_seen per simulated '
           'second (the camera runs at 10 Hz). Launch CPU per simulated second: the launch\'s CPU over the '
           'real-time factor, what a simulated second costs whatever else the machine does (on 2 free '
           'cores, 200 %% of it allows real time at best).' % fleet_sim.get('window_s', 0), '',
           _row(['robots', 'cameras', 'real-time factor', 'simulator CPU %', 'launch CPU %',
                 'launch CPU % per sim s', 'processes', 'machine CPU %', 'frames / sim s']),
           _row(['---'] * 9)]
    for s in fleet_sim.get('sizes', []):
        rtf = s['real_time_factor']
        out.append(_row([str(s['robots']), str(s['cameras']), '%.2f' % rtf if rtf is not None else '-',
                         '%.0f' % s['sim_cpu_pct'], '%.0f' % s['total_cpu_pct'],
                         '%.0f' % (s['total_cpu_pct'] / rtf) if rtf else '-', str(s['processes']),
                         '%.0f' % s['machine_cpu_pct'],
                         ', '.join('%s %s' % (r, '%.1f' % f if f is not None else '-')
                                   for r, f in sorted(s['frames_per_sim_s'].items()))]))
    names = sorted({name for s in fleet_sim.get('sizes', []) for name in s.get('cpu_by_process_pct', {})
                    if name not in ('sleep', 'roslaunch')})
    if names:
        out += ['', 'CPU by process (% of one core; each name\'s processes together; /proc cuts names at 15 '
                'characters):', '', _row(['robots'] + names), _row(['---'] * (len(names) + 1))]
        for s in fleet_sim.get('sizes', []):
            cpu = s.get('cpu_by_process_pct', {})
            out.append(_row([str(s['robots'])] + ['%.0f' % cpu.get(name, 0.0) for name in names]))
    ended = ['%s with %d robots: %s' % (r, s['robots'], res) for s in fleet_sim.get('sizes', [])
             for r, res in sorted(s.get('turns_ended_early', {}).items())]
    if ended:
        out += ['', 'Turns that ended within the window: ' + '; '.join(ended) + '.']
    return '\n'.join(out) + '\n'
