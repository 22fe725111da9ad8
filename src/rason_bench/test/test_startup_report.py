"""The start-up part's goals and section (rason_bench.startup_report) and its report action."""
from rason_bench import protocol, report, startup_report

RUNS = [{'to_first_cycle_s': s, 'cpu_s': 1.5, 'rss_mb': 108.0, 'rss_peak_mb': p} for s, p in ((0.8, 109.0), (1.3, 110.0), (0.9, 111.0))]


def startup(first_s, peak_mb):
    return {'runs': RUNS, 'to_first_cycle_s': first_s, 'cpu_s': 1.5, 'rss_mb': 108.0, 'rss_peak_mb': peak_mb,
            'cds': 'class-data sharing: on (/ws/jason_lib/target/rason-jason-lib.jsa)'}


def test_goals_are_met_by_the_medians():
    (cycle, cycle_text, cycle_met), (rss, rss_text, rss_met) = startup_report.goals(startup(0.9, 110.0))
    assert '<= 1 s' in cycle and cycle_met and cycle_text == '0.90 s (3 starts, 0.80–1.30 s; CPU 1.50 s)'
    assert '<= 200 MB' in rss and rss_met and rss_text.startswith('110 MB')


def test_goals_not_met():
    assert [met for _, _, met in startup_report.goals(startup(1.01, 200.5))] == [False, False]


def test_no_runs_no_goals_and_the_report_lists_them_first():
    assert startup_report.goals({}) == []
    assert report.goals({'startup': startup(0.9, 110.0)})[0][0].startswith('start-up of a one-agent rason_mas')


def test_the_section_has_a_row_per_start_and_the_node_s_sharing_line():
    text = startup_report.text(startup(0.9, 110.0))
    assert '| 2 | 1.30 | 1.50 | 108 | 110 |' in text
    assert 'class-data sharing: on' in text


def test_the_agent_reports_its_first_cycle_when_asked():
    assert protocol.go_started('startup', 3) == 'go_started(startup,3)'
    assert protocol.parse_report('started', ['3', '12345.678']) == protocol.Started(3, 12345.678)
