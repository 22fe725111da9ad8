"""rason_mas imports rospy without numpy (rason_bridge.lean_import): genpy then accepts plain
numbers only, numpy still imports afterwards, and nothing changes once it is imported."""
import subprocess
import sys

import pytest


def python(code):
    return subprocess.run([sys.executable, '-c', code], capture_output=True, text=True, check=True).stdout.split()


def test_rospy_imported_without_numpy_then_numpy_imports_as_ever():
    pytest.importorskip('numpy')
    pytest.importorskip('genpy')
    out = python('import sys\n'
                 'from rason_bridge.lean_import import without\n'
                 'with without("numpy"):\n'
                 '    import genpy.message\n'
                 'print("numpy" in sys.modules)\n'
                 'print(any(t.__module__ == "numpy" for t in genpy.message._valid_float_types))\n'
                 'import numpy\n'
                 'print(numpy.float64(2.5) + 1)\n')
    assert out == ['False', 'False', '3.5']


def test_a_module_already_imported_stays():
    pytest.importorskip('numpy')
    out = python('import sys, numpy\n'
                 'from rason_bridge.lean_import import without\n'
                 'with without("numpy"):\n'
                 '    import numpy as again\n'
                 'print(again is sys.modules["numpy"])\n')
    assert out == ['True']


def test_a_module_not_installed_stays_not_installed():
    out = python('import sys\n'
                 'from rason_bridge.lean_import import without\n'
                 'with without("no_such_module_here"):\n'
                 '    pass\n'
                 'print("no_such_module_here" in sys.modules)\n')
    assert out == ['False']


def _package(tmp_path):
    """A package whose __init__ imports its submodule heavy, which counts its runs."""
    pkg = tmp_path / 'pkg'
    pkg.mkdir()
    (pkg / '__init__.py').write_text('import pkg.heavy\n')
    (pkg / 'heavy.py').write_text('import builtins\nbuiltins.heavy_runs = getattr(builtins, "heavy_runs", 0) + 1\n'
                                  'VALUE = 42\n')
    return str(tmp_path)


def python_in(path, code):
    return subprocess.run([sys.executable, '-c', 'import sys\nsys.path.insert(0, %r)\n' % path + code],
                          capture_output=True, text=True, check=True).stdout.split()


def test_a_deferred_submodule_runs_at_its_first_use_only(tmp_path):
    out = python_in(_package(tmp_path),
                    'import builtins\n'
                    'from rason_bridge.lean_import import deferred\n'
                    'with deferred("pkg.heavy"):\n'
                    '    import pkg\n'
                    'print(getattr(builtins, "heavy_runs", 0))\n'
                    'print(pkg.heavy is sys.modules["pkg.heavy"])\n'
                    'import pkg.heavy\n'
                    'print(getattr(builtins, "heavy_runs", 0))\n'
                    'print(pkg.heavy.VALUE, builtins.heavy_runs)\n'
                    'print(pkg.heavy.VALUE, builtins.heavy_runs, type(pkg.heavy).__name__)\n')
    assert out == ['0', 'True', '0', '42', '1', '42', '1', 'module']


def test_a_submodule_already_imported_or_missing_is_left_as_it_is(tmp_path):
    out = python_in(_package(tmp_path),
                    'import builtins, pkg\n'
                    'from rason_bridge.lean_import import deferred\n'
                    'with deferred("pkg.heavy"), deferred("pkg.nowhere"), deferred("toplevel"):\n'
                    '    import pkg.heavy\n'
                    'print(builtins.heavy_runs, type(pkg.heavy).__name__)\n'
                    'print("pkg.nowhere" in sys.modules, "toplevel" in sys.modules)\n')
    assert out == ['1', 'module', 'False', 'False']


def test_rospy_imports_without_running_roslib_stacks():
    pytest.importorskip('rospy')
    out = python('import sys\n'
                 'from rason_bridge.lean_import import deferred\n'
                 'with deferred("roslib.stacks"):\n'
                 '    import rospy\n'
                 'print("catkin_pkg" in sys.modules)\n'
                 'import roslib\n'
                 'print(callable(roslib.stacks.list_stacks), "catkin_pkg" in sys.modules)\n')
    assert out == ['False', 'True', 'True']
