# Type stubs of rpt.cameras (see __init__.pyi).
import os
from collections.abc import Sequence

from . import Camera

def load(path: str | os.PathLike[str], *, format: str = "auto", units: str = "default", image_width: int = 0,
         image_height: int = 0) -> list[Camera]: ...
def save(path: str | os.PathLike[str], cameras: Sequence[Camera], *, format: str = "auto",
         units: str = "default") -> None: ...
