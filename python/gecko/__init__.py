"""gecko — mechanics of gecko-like adhesion.

Kernels (C++ header-only library, compiled here as ``gecko._core``):

* elliptic integrals: ``ellint_f``, ``ellint_e``, ``ellint_k``, ``ellint_ek`` and the Carlson
  symmetric forms ``carlson_rf``, ``carlson_rd``, ``carlson_rj``, ``carlson_rc``; all broadcast
  like numpy ufuncs and raise ``ValueError`` on a domain error (or give NaN with ``errors="nan"``).

Each concern lives in its own module and lists its public names in its own ``__all__``.
"""
from ._core import __version__
from . import elliptic as _elliptic
from .elliptic import *  # noqa: F401,F403
from . import seta as _seta
from .seta import *  # noqa: F401,F403
from . import friction as _friction
from .friction import *  # noqa: F401,F403

__all__ = ["__version__", *_elliptic.__all__, *_seta.__all__, *_friction.__all__]
