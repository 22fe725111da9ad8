"""Start mosquitto (an MQTT broker, not a ROS node) from a config template of the rason package.

The templates in config/mosquitto/ name what differs per run as @LISTEN@, @PORT@, @FLEET@
(ADDR:PORT of the fleet broker, for a bridged local broker) and @ROBOT@. This renders one into a
private temporary folder, runs mosquitto on it in the foreground, passes SIGINT/SIGTERM on (so
the broker stops with its roslaunch) and removes the folder when mosquitto ends.

  mosquitto_broker --config FILE [--listen ADDR] [--port P] [--fleet ADDR:PORT] [--robot NAME]

The listener is refused unless ADDR is loopback or inside 198.18.0.0/15 (the hosts harness).
"""
import argparse
import os
import re
import shutil
import signal
import subprocess
import sys
import tempfile

from .addresses import check_bind_address, split_host_port

PLACEHOLDER = re.compile(r'@([A-Z_]+)@')


def render(template, values):
    """template with every @NAME@ replaced by values['NAME']; a missing value is an error."""
    missing = sorted({name for name in PLACEHOLDER.findall(template) if not values.get(name)})
    if missing:
        raise ValueError('the config needs %s' % ', '.join(
            '--%s' % name.lower() for name in missing))
    return PLACEHOLDER.sub(lambda m: str(values[m.group(1)]), template)


def _arguments(argv):
    parser = argparse.ArgumentParser(prog='mosquitto_broker', description=__doc__.split('\n')[0])
    parser.add_argument('--config', required=True,
                        help='a template, e.g. config/mosquitto/fleet.conf')
    parser.add_argument('--listen', default='127.0.0.1')
    parser.add_argument('--port', type=int, default=1883)
    parser.add_argument('--fleet', default='', help='ADDR:PORT of the fleet broker (bridge config); none: no fleet')
    parser.add_argument('--robot', default='', help='robot name (bridge client ids); none: no robot')
    parser.add_argument('--mosquitto', default='mosquitto', help='the broker executable')
    # roslaunch appends __name:=... and __log:=...
    args = parser.parse_args([a for a in argv if ':=' not in a])
    # broker.launch's defaults: a launch arg with an empty default would be listed as required
    args.fleet, args.robot = ['' if v == 'none' else v for v in (args.fleet, args.robot)]
    return args


def main(argv=None):
    args = _arguments(sys.argv[1:] if argv is None else argv)
    try:
        check_bind_address(args.listen)
        if args.fleet:
            split_host_port(args.fleet)
        with open(args.config) as f:
            text = render(f.read(), {'LISTEN': args.listen, 'PORT': args.port,
                                     'FLEET': args.fleet, 'ROBOT': args.robot})
    except (OSError, ValueError) as error:
        sys.exit('mosquitto_broker: %s' % error)
    folder = tempfile.mkdtemp(prefix='rason-mosquitto-')
    try:
        config = os.path.join(folder, 'mosquitto.conf')
        with open(config, 'w') as f:
            f.write(text)
        broker = subprocess.Popen([args.mosquitto, '-c', config])

        def forward(signum, _frame):
            broker.send_signal(signum)
        for signum in (signal.SIGINT, signal.SIGTERM):
            signal.signal(signum, forward)
        return broker.wait()
    finally:
        shutil.rmtree(folder, ignore_errors=True)


if __name__ == '__main__':
    sys.exit(main())
