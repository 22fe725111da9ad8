"""Why a wiring node found no ``~perceptions`` (``~actions``): where it looked, what it found
near by and what to change. A wiring file comes in two layouts and each works only where it is
loaded:

- inside the ``<node>`` (``robot.launch perceptions:=FILE``, ``<rosparam command="load">`` in
  the node element): ``perceptions:`` (``actions:``) at the file's top level;
- into the robot's namespace (``<rosparam command="load">`` in the ``<group ns>``, as
  ``patrol.launch`` loads ``agents/patrol/wiring.yaml``): wrapped in the node's name,
  ``generic_synthesizer:`` / ``generic_decomposer:``.

No rospy: the caller hands the parameter server (``rospy`` itself, or a stand-in)."""
from rason_wiring.config import ConfigError

#: What each wiring key configures and how a file that holds it is given to its node.
_GIVEN = {
    'perceptions': 'robot.launch perceptions:=FILE',
    'actions': '<rosparam command="load" file="FILE"/> inside the <node> element',
}


def _join(namespace, name):
    return namespace.rstrip('/') + '/' + name


def _parts(name):
    return [p for p in name.split('/') if p]


def _holders(key, base, names):
    """The names X below ``base`` with parameters under ``base/X/key`` (leaf names: a dict is
    listed by its leaves)."""
    depth = len(_parts(base))
    found = set()
    for n in names:
        parts = _parts(n)
        if parts[:depth] == _parts(base) and len(parts) > depth + 1 and parts[depth + 1] == key:
            found.add(parts[depth])
    return sorted(found)


def missing(key, node, namespace, names):
    """The explanation, for the ``[FATAL]`` line, of a ``~key`` that is not set.

    :param key: 'perceptions' or 'actions'
    :param node: the node's full name, e.g. '/rover/generic_synthesizer'
    :param namespace: the node's namespace, e.g. '/rover/'
    :param names: every parameter name on the server
    """
    private = node.rstrip('/')
    own_name = private.rsplit('/', 1)[-1]
    looked = '~%s is not set (looked for %s' % (key, _join(private, key))
    wrappers = _holders(key, private, names)
    if wrappers:        # a wrapped file loaded into the node: ~generic_synthesizer/perceptions
        depth = len(_parts(private))
        top = sorted({_parts(n)[depth] for n in names
                      if _parts(n)[:depth] == _parts(private) and len(_parts(n)) > depth})
        return ('%s, found %s): the wiring file loaded into this node has `%s:` at its top level (its top-level '
                'keys: %s), the layout for loading into the robot\'s namespace, as patrol.launch loads '
                'agents/patrol/wiring.yaml; a file given as %s needs `%s:` at its top level: remove the `%s:` '
                'line and unindent what it holds'
                % (looked, _join(_join(private, wrappers[0]), key), wrappers[0], ', '.join(top), _GIVEN[key], key,
                   wrappers[0]))
    flat = _join(namespace, key)
    if any(n == flat or n.startswith(flat + '/') for n in names):
        return ('%s, found %s): a file with `%s:` at its top level was loaded into the namespace %s, not into '
                'this node: give it as %s, or wrap what it holds in `%s:`'
                % (looked, flat, key, namespace, _GIVEN[key], own_name))
    others = [o for o in _holders(key, namespace, names) if o != own_name]
    if others:
        return ('%s; in the namespace only %s): the wiring is there under another node\'s name: name this node '
                '%s, or the file\'s top-level key %s'
                % (looked, ', '.join(_join(_join(namespace, o), key) for o in others), others[0], own_name))
    return ('%s and %s): give this node a wiring file with `%s:` at its top level as %s'
            % (looked, flat, key, _GIVEN[key]))


def wiring_param(key, server):
    """``~key`` from ``server`` (``has_param``, ``get_param``, ``get_name``, ``get_namespace``,
    ``get_param_names``: rospy's); when it is not set, :class:`ConfigError` says why."""
    if not server.has_param('~' + key):
        raise ConfigError(missing(key, server.get_name(), server.get_namespace(), server.get_param_names()))
    return server.get_param('~' + key)
