"""The thesis's measurements (Tables 7.1-7.4), to print beside ours.

Per run: (fault detection, robot location, diagnosis, total) in seconds; None where the
thesis has no value (run 5 of Table 7.2 never found Faulty: "∞"). The thesis has no runs
without a fault. ``STATED_TOTAL`` is the mean total the text gives (computed over the
successful runs; for the left actuator the text says 30.25 where the table gives 30.35).
"""

TABLES = {
    'both_actuators': ('7.1', [(4.3, 14.7, 4.4, 23.4), (4.0, 14.2, 4.7, 22.9),
                               (4.5, 13.8, 4.2, 22.5), (4.1, 12.4, 4.9, 21.4),
                               (4.5, 13.1, 4.4, 22.0)]),
    'odometry': ('7.2', [(7.1, 7.4, 7.0, 21.5), (6.7, 7.0, 6.1, 19.8), (6.6, 8.7, 5.7, 21.0),
                         (7.3, 8.5, 5.8, 21.6), (7.3, 62.3, None, None),
                         (7.7, 35.1, 5.1, 47.9), (6.7, 8.8, 5.9, 21.5)]),
    'left_actuator': ('7.3', [(18.5, 0.9, 10.3, 29.7), (19.2, 1.6, 11.3, 32.1),
                              (18.1, 2.4, 10.5, 31.0), (17.8, 1.4, 9.4, 28.6)]),
    'right_actuator': ('7.4', [(17.6, 10.6, 11.3, 39.5), (18.9, 9.2, 14.2, 42.3),
                               (16.9, 11.9, 13.1, 41.9), (15.6, 10.8, 12.8, 39.2)]),
}

STATED_TOTAL = {'both_actuators': (22.42, 0.78), 'odometry': (25.55, 10.97),
                'left_actuator': (30.25, 1.52), 'right_actuator': (40.73, 1.60)}


def step_means(fault):
    """Mean of each column of the fault's table over the runs that have a value, or None
    when the thesis has no table for the fault.

    :rtype: tuple of 4 floats, or None
    """
    if fault not in TABLES:
        return None
    rows = TABLES[fault][1]
    means = []
    for col in range(4):
        values = [r[col] for r in rows if r[col] is not None]
        means.append(sum(values) / len(values))
    return tuple(means)
