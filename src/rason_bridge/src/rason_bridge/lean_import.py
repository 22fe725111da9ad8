"""Importing less at start-up (no rospy here: this runs before it is imported).

- Without an optional module: genpy imports numpy, if it can, only to accept numpy numbers in
  message fields. rason_mas never publishes any; imported without numpy, the node starts
  about 0.1 s sooner and takes 15 MB less.
- A module deferred to its first use: rospy imports roslib, whose package imports
  roslib.stacks, which imports catkin and catkin_pkg to find packages; rospy never uses it.
"""
import contextlib
import importlib.machinery
import importlib.util
import sys
import types


@contextlib.contextmanager
def without(name):
    """Inside, ``import name`` fails as if it were not installed (ImportError), so optional
    uses of it are skipped; afterwards it imports as ever. Nothing changes when it is already
    imported."""
    if sys.modules.get(name) is not None:
        yield
        return
    had, saved = name in sys.modules, sys.modules.get(name)
    sys.modules[name] = None
    try:
        yield
    finally:
        if had:
            sys.modules[name] = saved
        else:
            del sys.modules[name]


class _Deferred(types.ModuleType):
    """A module not run yet: the first attribute it lacks runs it (``__spec__`` and the other
    import attributes are set, so importing it again does not)."""

    def __getattr__(self, attr):
        self.__class__ = types.ModuleType
        self.__spec__.loader.exec_module(self)
        return getattr(self, attr)


@contextlib.contextmanager
def deferred(name):
    """Inside, the submodule ``name`` (``package.module``) is imported without running it: it
    runs when one of its attributes is first used. Its package is not imported here; on the
    way out, the package (if imported meanwhile) gets it as an attribute, as an import would
    have set. Nothing changes when it is already imported or cannot be found."""
    package, _, attr = name.rpartition('.')
    spec = None
    if name not in sys.modules and package:
        parent = importlib.util.find_spec(package)
        if parent is not None and parent.submodule_search_locations:
            spec = importlib.machinery.PathFinder.find_spec(name, parent.submodule_search_locations)
    if spec is None or spec.loader is None:
        yield
        return
    module = importlib.util.module_from_spec(spec)
    module.__class__ = _Deferred
    sys.modules[name] = module
    yield
    owner = sys.modules.get(package)
    if owner is not None and attr not in vars(owner):
        setattr(owner, attr, module)
