"""The fleet part's goals and Markdown (pure: the ``fleet`` dict of results.json in, text out).
A goal whose measurement was skipped (no root for network namespaces) has met None."""
import math

#: Issue 30's goals.
RTT_P99_GOAL_MS = 20.0
RATE_P99_BOUND_MS = 100.0
RATE_GOAL_PER_S = 2000.0
DEPARTURE_GOAL_MS = 2000.0
FALSE_DEPARTURE_GOAL_LOSS = 10


def _ms(x):
    return 'inf' if x is None or x == math.inf else '%.1f' % x


def _rtt_goal(where, part):
    goal = 'fleet: achieve round trip between two rason_mas over MQTT, %s, p99 <= %g ms' % (where, RTT_P99_GOAL_MS)
    if part.get('skipped'):
        return (goal, 'skipped: %s' % part['skipped'], None)
    s = part['round_trip_ms']
    if not s['n']:
        return (goal, 'no round trip', False)
    return (goal, 'p50 %.2f ms, p99 %.2f ms (%d round trips)' % (s['p50'], s['p99'], s['n']),
            s['p99'] <= RTT_P99_GOAL_MS)


def _rate_goal(rate):
    goal = 'fleet: message rate with p99 <= %g ms (a rason_mas answering each) >= %g/s' % (
        RATE_P99_BOUND_MS, RATE_GOAL_PER_S)
    within, beyond = rate.get('highest_within'), rate.get('lowest_beyond')
    if within is None:
        return (goal, 'p99 above %g ms at the lowest rate tried' % RATE_P99_BOUND_MS, False)
    text = 'within up to %.0f/s; %s' % (within, 'passed at %.0f/s' % beyond if beyond is not None
                                         else 'not passed up to the highest rate tried')
    return (goal, text, within >= RATE_GOAL_PER_S)


def departure_verdict(dep):
    """(measured text, met): every killed robot's departure noticed, the slowest within the goal."""
    single, batch = dep['single_ms'], dep['batch_ms']
    worst = max([s['max'] for s in (single, batch) if s['n']] or [math.inf])
    unnoticed = dep.get('unnoticed', [])
    text = 'slowest %s ms (one at a time: p50 %s ms of %d; %d at once: max %s ms)' % (
        _ms(worst), _ms(single.get('p50')), single['n'], dep['batch'], _ms(batch.get('max')))
    if unnoticed:
        text += '; %d never noticed' % len(unnoticed)
    return text, not unnoticed and worst <= DEPARTURE_GOAL_MS


def _false_goal(false):
    goal = 'fleet: false departures at %d %% loss (across namespaces, %s robots) = 0' % (
        FALSE_DEPARTURE_GOAL_LOSS, false.get('robots', '?'))
    if false.get('skipped'):
        return (goal, 'skipped: %s' % false['skipped'], None)
    level = next((l for l in false['levels'] if l['loss_percent'] == FALSE_DEPARTURE_GOAL_LOSS), None)
    if level is None:
        return (goal, 'not measured', False)
    return (goal, '%d in %g s (%.1f per 10 min)' % (level['departures'], false['window_s'], level['per_10_min']),
            level['departures'] == 0)


def goals(fleet):
    """[(goal, measured, met)] for what is in fleet; met None when skipped."""
    out = []
    for key, where in (('loopback', 'loopback'), ('namespaces', 'across network namespaces')):
        if key in fleet:
            out.append(_rtt_goal(where, fleet[key]))
    if 'rate' in fleet:
        out.append(_rate_goal(fleet['rate']))
    dep = fleet.get('departures')
    if dep:
        text, met = departure_verdict(dep)
        out.append(('fleet: departure (connection ended) noticed by an observing rason_mas among %d robots <= %g ms'
                    % (dep['robots'], DEPARTURE_GOAL_MS), text, met))
    if 'false_departures' in fleet:
        out.append(_false_goal(fleet['false_departures']))
    return out


def _row(cells):
    return '| ' + ' | '.join(cells) + ' |'


def text(fleet):
    """Markdown: the fleet part's tables."""
    out = ['Over `~fleet_channel: mqtt` through mosquitto (`config/mosquitto/fleet.conf`, `set_tcp_nodelay`), '
           'fleet authentication on (every message and presence signed and checked).', '']
    rows = [(k, w) for k, w in (('loopback', 'loopback'), ('namespaces', 'network namespaces')) if k in fleet]
    if rows:
        out += ['Achieve round trip alice → bob → alice (`agents/fleet.asl`: two rason_mas, one after the other, '
                'timed by alice with `rason.time_ms`):', '',
                _row(['where', 'n', 'p50 ms', 'p90 ms', 'p99 ms', 'max ms']), _row(['---'] * 6)]
        for key, where in rows:
            part = fleet[key]
            if part.get('skipped'):
                out.append(_row([where, 'skipped: %s' % part['skipped'], '', '', '', '']))
                continue
            s = part['round_trip_ms']
            out.append(_row([where, '%d (after %d)' % (s['n'], part['warmup'])] +
                            (['%.2f' % s[k] for k in ('p50', 'p90', 'p99', 'max')] if s['n'] else [''] * 4)))
        out.append('')
    rate = fleet.get('rate')
    if rate:
        out += ['Message rate (loopback): a simulated robot (`SimulatedFleet`) sends `achieve echo(Run, Seq)` to bob '
                'on a fixed schedule for %g s per step; bob answers each with `achieve echoed(Run, Seq)`; '
                'each answer timed from when its message was due (an unanswered one counts as slower than any).'
                % rate['seconds_per_step'] + (' First a warm-up of %g s a step, while both JVMs compile the message '
                                              'path (its steps marked "warm-up", not counted).'
                                              % rate['warmup_seconds_per_step'] if rate.get('warmup') else ''), '',
                _row(['offered /s', 'achieved /s', 'answered', 'p50 ms', 'p99 ms', 'max ms']), _row(['---'] * 6)]
        for s in [dict(w, warmup=True) for w in rate.get('warmup', [])] + rate['steps']:
            out.append(_row(['%.0f%s' % (s['rate'], ' (warm-up)' if s.get('warmup') else ''),
                             '%.0f' % (s['achieved_rate'] or 0),
                             '%d of %d' % (s['answered'], s['sent']), _ms(s['p50_ms']), _ms(s['p99_ms']),
                             _ms(s['max_ms'])]))
        out.append('')
    dep = fleet.get('departures')
    if dep:
        out += ['Departures (loopback): %d simulated robots (one JVM, each an MQTT connection that signs its '
                'presence and will as rason_mas does), one rason_mas observing (`present/1` beliefs). %d robots\' '
                'connections end one at a time, then %d at once (the broker sends their wills); from the kill to '
                'the observer\'s `-present` event: one at a time p50 %s ms, max %s ms; at once max %s ms.%s'
                % (dep['robots'], dep['singles'], dep['batch'], _ms(dep['single_ms'].get('p50')),
                   _ms(dep['single_ms'].get('max')), _ms(dep['batch_ms'].get('max')),
                   ' Other departures noticed meanwhile: %s.' % ', '.join('sim%d' % i for i in dep['other_departures'])
                   if dep.get('other_departures') else ''), '']
    false = fleet.get('false_departures')
    if false:
        if false.get('skipped'):
            out += ['False departures: skipped (%s).' % false['skipped'], '']
        else:
            out += ['False departures (network namespaces): %d simulated robots on one host, the observer on another, '
                    'the broker on a third; for %g s per level the robots\' link loses that share of its frames in '
                    'each direction (observer and broker links clean) and no robot leaves: departures the observer '
                    'noticed all the same, and scaled to 10 minutes.' % (false['robots'], false['window_s']), '',
                    _row(['loss', 'departures', 'robots', 'per 10 min']), _row(['---'] * 4)]
            for l in false['levels']:
                out.append(_row(['%d %%' % l['loss_percent'], '%d' % l['departures'], '%d' % l['robots_affected'],
                                 '%.1f' % l['per_10_min']]))
            out.append('')
    return '\n'.join(out) + '\n'
