# Type stubs of rpt.export (see __init__.pyi).
import os
import pathlib
from collections.abc import Sequence

from . import Predictions

def formats() -> list[str]: ...
def write(out_dir: str | os.PathLike[str], predictions: Predictions | Sequence[Predictions],
          formats: str | Sequence[str] = "json", *, filled_joints: bool = True, predicted_joints: bool = True,
          trc_axes: str = "z-up", trc_units: str = "m", run_id: str = "python") -> list[pathlib.Path]: ...
