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
