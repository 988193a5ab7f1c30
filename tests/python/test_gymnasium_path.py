"""With Gymnasium importable, colav's environments are gymnasium.Env / gymnasium.vector.VectorEnv
subclasses with gymnasium.spaces.Box spaces. Gymnasium is not a Debian package: without it, this
runs test_api.py against a stand-in of its interface (gymnasium_stand_in/)."""

import os
import pathlib
import subprocess
import sys

HERE = pathlib.Path(__file__).parent


def test_api_checks_pass_with_gymnasium_importable():
    path = os.environ.get("PYTHONPATH", "")
    try:
        import gymnasium  # noqa: F401  (the real one is installed: check against it)
    except ImportError:
        path = os.pathsep.join([str(HERE / "gymnasium_stand_in"), path])
    check = ("import colav, sys, pytest; assert colav.gymnasium is not None; "
             "sys.exit(pytest.main(['-q', '-p', 'no:cacheprovider', sys.argv[1]]))")
    result = subprocess.run([sys.executable, "-c", check, str(HERE / "test_api.py")],
                            capture_output=True, text=True, env={**os.environ, "PYTHONPATH": path})
    assert result.returncode == 0, result.stdout + result.stderr
