"""A stand-in for the parts of Gymnasium 1.x that colav uses (Gymnasium is not packaged for
Debian 12): test_gymnasium_path.py checks that with a `gymnasium` importable, colav's classes
subclass its Env and VectorEnv and use its Box. Signatures follow gymnasium/core.py,
gymnasium/vector/vector_env.py and gymnasium/spaces/box.py."""

import numpy as np

from . import spaces, vector


class Env:
    metadata = {"render_modes": []}
    render_mode = None
    spec = None
    _np_random = None

    def reset(self, *, seed=None, options=None):
        if seed is not None:
            self._np_random = np.random.default_rng(seed)

    def close(self):
        pass
