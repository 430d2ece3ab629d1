# Type stubs of rpt.synthetic (see __init__.pyi).
from typing import SupportsIndex

from . import datasets

def detector_profiles() -> list[str]: ...
def scene(*, cameras: SupportsIndex = 5, people: SupportsIndex = 4, frames: SupportsIndex = 300,
          fps: SupportsIndex = 25, joints: str = "body", layout: str = "ring", distortion: str = "none",
          noise: str = "realistic", seed: SupportsIndex = 1) -> datasets.Sequence: ...
def simulate(sequence: datasets.Sequence, detector: str = "realistic", seed: SupportsIndex = 1) -> datasets.Sequence: ...
