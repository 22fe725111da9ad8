"""Text of the nftables rules and tc arguments that shape one host's link (pure functions).

A host's link is the veth pair between its namespace and the switch's bridge. Loss and cuts
are rules of a bridge-family table in the switch namespace, one table per host, so frames are
lost on the wire: the sender's stack never learns of the drop (an output-hook drop in the host
itself would fail the send with EPERM, which no real lossy link does).
"""


def table_name(host):
    return 'rason_link_' + host.replace('-', '_')


def link_ruleset(host, port, loss_percent=0, cut=False):
    """An nft script that atomically replaces the host's table.

    port: the switch-side interface of the host's veth. Loss applies to IP frames of each
    direction independently (a round trip through this link survives with (1-p)^2); ARP is
    spared so that loss never turns into a stale neighbour entry. A cut drops every frame.
    """
    if not 0 <= loss_percent <= 100:
        raise ValueError('loss_percent must be within 0..100, not %r' % (loss_percent,))
    table = table_name(host)
    rules = []
    for match in ('iifname "%s"' % port, 'oifname "%s"' % port):
        if cut:
            rules.append('%s drop' % match)
        elif loss_percent:
            rules.append('%s ether type { ip, ip6 } numgen random mod 100 < %d drop'
                         % (match, int(loss_percent)))
    body = ''.join('    %s\n' % rule for rule in rules)
    # "add" first so that "delete" cannot fail on the first call; the three run as one transaction.
    return ('add table bridge {t}\n'
            'delete table bridge {t}\n'
            'table bridge {t} {{\n'
            '  chain forward {{\n'
            '    type filter hook forward priority 0; policy accept;\n'
            '{body}'
            '  }}\n'
            '}}\n').format(t=table, body=body)


def parse_rate_bits(rate):
    """'1mbit', '500kbit', '2gbit', '64000bit' or a number of bit/s -> bit/s (int)."""
    if isinstance(rate, (int, float)):
        bits = float(rate)
    else:
        text = rate.strip().lower()
        units = (('gbit', 1e9), ('mbit', 1e6), ('kbit', 1e3), ('bit', 1.0))
        for suffix, scale in units:
            if text.endswith(suffix):
                bits = float(text[:-len(suffix)]) * scale
                break
        else:
            bits = float(text)
    if bits <= 0:
        raise ValueError('rate must be positive, not %r' % (rate,))
    return int(bits)


def tbf_args(device, rate, latency_ms=200):
    """tc arguments that limit the egress of device to rate (token bucket filter).

    The bucket holds 20 ms worth of bytes but at least two full frames, so that small rates
    still pass a maximum-size frame.
    """
    bits = parse_rate_bits(rate)
    burst = max(2 * 1514, bits // 8 // 50)
    return ['qdisc', 'replace', 'dev', device, 'root', 'tbf', 'rate', '%dbit' % bits,
            'burst', str(burst), 'latency', '%dms' % latency_ms]


def tbf_delete_args(device):
    return ['qdisc', 'del', 'dev', device, 'root']
