"""``rosrun rason_bridge fleet_key [PATH] [--force] [--print]``: makes the fleet's shared key.

Writes a new random key (Python's ``secrets``) to PATH (default
``$ROS_HOME/rason/fleet.key``, where rason_mas looks for it), readable by its
owner only, and refuses to overwrite an existing file unless ``--force``.
Copy the same file to every robot of the fleet. ``--print`` writes nothing and
prints a new key line, e.g. to add as the second line of the file when
rotating keys.
"""
import argparse
import hashlib
import os
import secrets
import sys

#: Random bytes of a key; written as hex text, which is what rason_mas uses as the key's bytes.
KEY_BYTES = 32
HEADER = ('# Rason fleet key: the same file on every robot of the fleet (keep it secret, mode 0600).\n'
          '# One key per line; the first signs, every line is accepted (to rotate, see the README, "Security").\n')


def generate_key():
    """A new key: 64 hex digits of a cryptographically random 32-byte number."""
    return secrets.token_hex(KEY_BYTES)


def write_key(path, key, force=False):
    """Write a key file holding ``key``, mode 0600 (its folders made 0700 if missing).

    :raises FileExistsError: path exists and ``force`` is false
    """
    folder = os.path.dirname(os.path.abspath(path))
    os.makedirs(folder, mode=0o700, exist_ok=True)
    flags = os.O_WRONLY | os.O_CREAT | (os.O_TRUNC if force else os.O_EXCL)
    fd = os.open(path, flags, 0o600)
    try:
        os.fchmod(fd, 0o600)  # an overwritten file may have had a looser mode
        os.write(fd, (HEADER + key + '\n').encode('ascii'))
    finally:
        os.close(fd)


#: Shorter secrets are refused, as rason_mas refuses them: 32 bytes is HMAC-SHA256's key size.
MIN_KEY_BYTES = 32


def key_id(secret):
    """The id that names a key in signed messages: the first 4 bytes of its SHA-256, in hex
    (what rason_mas logs as ``signed with key …``)."""
    return hashlib.sha256(secret).hexdigest()[:8]


def parse_keys(text, origin='the fleet key'):
    """The keys of a key file's text, as rason_mas reads them: one a line, blank lines and
    ``#`` lines skipped, blanks around trimmed, the line's UTF-8 bytes the secret; the first
    signs, every one verifies.

    :returns: a list of ``(key_id, secret)``, the signing key first
    :raises ValueError: no key, a key shorter than :data:`MIN_KEY_BYTES`, two keys with one id
    """
    keys = []
    for line in text.splitlines():
        line = line.strip()
        if not line or line.startswith('#'):
            continue
        secret = line.encode('utf-8')
        if len(secret) < MIN_KEY_BYTES:
            raise ValueError('%s: a key of %d bytes is too short (at least %d; make one with '
                             '`rosrun rason_bridge fleet_key`)' % (origin, len(secret), MIN_KEY_BYTES))
        if any(key_id(secret) == known for known, _ in keys):
            raise ValueError('%s: two keys with the id %s' % (origin, key_id(secret)))
        keys.append((key_id(secret), secret))
    if not keys:
        raise ValueError('%s holds no key (make one with `rosrun rason_bridge fleet_key`)' % origin)
    return keys


def read_keys(path):
    """:func:`parse_keys` of the file at ``path``.

    :raises OSError: the file cannot be read
    :raises ValueError: as :func:`parse_keys`
    """
    with open(path, encoding='utf-8') as f:
        return parse_keys(f.read(), path)


def make_new_key(path):
    """Write a new key to ``path`` (which must not exist yet)."""
    write_key(path, generate_key())


def main(argv=None, ros_home=None):
    from rason_bridge.fleet_auth import default_key_file
    parser = argparse.ArgumentParser(prog='fleet_key', description=__doc__.split('\n\n')[1],
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument('path', nargs='?', help='key file to write (default: $ROS_HOME/rason/fleet.key)')
    parser.add_argument('--force', action='store_true', help='overwrite an existing key file')
    parser.add_argument('--print', action='store_true', dest='print_only',
                        help='print a new key line instead of writing a file')
    args = parser.parse_args(argv)
    if args.print_only:
        print(generate_key())
        return 0
    if args.path:
        path = args.path
    else:
        if ros_home is None:
            import rospkg
            ros_home = rospkg.get_ros_home()
        path = default_key_file(ros_home)
    try:
        write_key(path, generate_key(), force=args.force)
    except FileExistsError:
        print('fleet_key: %s exists; not overwritten (use --force to replace it: every robot then needs the new '
              'file)' % path, file=sys.stderr)
        return 1
    except OSError as e:
        print('fleet_key: cannot write %s: %s' % (path, e), file=sys.stderr)
        return 1
    print('fleet_key: wrote a new fleet key to %s (mode 0600); copy this file to every robot of the fleet' % path)
    return 0


if __name__ == '__main__':
    sys.exit(main())
