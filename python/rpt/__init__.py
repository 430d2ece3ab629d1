"""rpt: multi-view, multi-person 3D pose triangulation (RapidPoseTriangulation), its dataset readers,
metrics and exports, from Python at C++ speed. docs/python.md."""
import sys as _sys

from ._rpt import (Camera, ConfigError, InputError, InputFileNotFoundError, InputWarning, Options, OutputError,
                   Predictions, Triangulator, cameras, datasets, export, metrics, synthetic)

# `import rpt.cameras` and `from rpt.datasets import open` work like for files of the package.
for _name in ("cameras", "datasets", "export", "metrics", "synthetic"):
    _sys.modules[__name__ + "." + _name] = globals()[_name]
del _name

__all__ = ["Camera", "ConfigError", "InputError", "InputFileNotFoundError", "InputWarning", "Options", "OutputError", "Predictions",
           "Triangulator", "cameras", "datasets", "export", "metrics", "synthetic"]
