"""The thesis's measurements (§5.5): ms per reasoning cycle of Listing 5.4 on a 1.8 GHz
dual-core AMD64, by number of perceptions (rows) and publishing rate in Hz (columns)."""

PERCEPTIONS = (1, 3, 5, 10)
RATES_HZ = (1, 3, 5, 10, 30, 50)

#: Table 5.1: no perception filtering.
TABLE_5_1 = {
    1: (0.48, 0.50, 0.49, 0.57, 0.89, 1.12),
    3: (0.50, 0.54, 0.56, 0.57, 1.03, 1.24),
    5: (0.54, 0.57, 0.67, 0.83, 1.35, 1.88),
    10: (0.64, 0.99, 1.04, 1.05, 2.26, 6.23),
}

#: Table 5.2: per-source filtering.
TABLE_5_2 = {
    1: (0.49, 0.50, 0.53, 0.55, 0.75, 0.85),
    3: (0.52, 0.58, 0.59, 0.71, 1.10, 1.32),
    5: (0.53, 0.60, 0.68, 0.85, 1.25, 1.68),
    10: (0.61, 0.77, 0.85, 1.17, 2.09, 2.58),
}

#: The bridge's two modes, as the perception_manager option names them, and the thesis table of each.
TABLES = {'accumulate': TABLE_5_1, 'per_source': TABLE_5_2}

#: With filtering, 10 perceptions x 50 Hz over 1 perception x 1 Hz (the thesis had no run
#: without traffic; its lightest cell is the nearest thing to a baseline): 2.58 / 0.49 = 5.3.
THESIS_SLOWDOWN = round(TABLE_5_2[10][-1] / TABLE_5_2[1][0], 1)


def thesis_ms(mode, perceptions, rate_hz):
    """The thesis's ms per cycle for a cell, or None when the thesis did not measure it."""
    table = TABLES.get(mode)
    if table is None or perceptions not in table or rate_hz not in RATES_HZ:
        return None
    return table[perceptions][RATES_HZ.index(rate_hz)]
