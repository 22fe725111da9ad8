"""rosrun rason hosts cleanup [--all] [--prefix P] | list: leftovers of the hosts harness."""
import argparse
import sys

from .hosts import DEFAULT_PREFIX, cleanup, list_namespaces


def main(argv=None):
    parser = argparse.ArgumentParser(prog='hosts', description=__doc__)
    sub = parser.add_subparsers(dest='command', required=True)
    clean = sub.add_parser('cleanup', help='remove the namespaces of runs whose process is gone')
    clean.add_argument('--all', action='store_true', help='also remove runs still alive')
    clean.add_argument('--prefix', default=DEFAULT_PREFIX)
    listing = sub.add_parser('list', help='the namespaces of the harness')
    listing.add_argument('--prefix', default=DEFAULT_PREFIX)
    args = parser.parse_args(argv)
    if args.command == 'list':
        for namespace in list_namespaces():
            if namespace.startswith(args.prefix + '-'):
                print(namespace)
        return 0
    removed = cleanup(args.prefix, all_runs=args.all)
    for namespace in removed:
        print('removed %s' % namespace)
    if not removed:
        print('nothing to remove')
    return 0


if __name__ == '__main__':
    sys.exit(main())
