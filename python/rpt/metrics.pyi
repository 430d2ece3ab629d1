# Type stubs of rpt.metrics (see __init__.pyi).
from collections.abc import Mapping, Sequence
from typing import Any, overload

import numpy.typing as npt

from . import Options, Predictions
from . import datasets

# The summary of `rpt eval --json`: on sequences and their predictions, or on arrays per frame
# (persons, joints, 4) with the joints named.
@overload
def evaluate(gt: datasets.Sequence | Sequence[datasets.Sequence], predictions: Predictions | Sequence[Predictions], *,
             options: Options | Mapping[str, Any] | None = None, **metric_options: Any) -> dict[str, Any]: ...
@overload
def evaluate(gt: Sequence[npt.ArrayLike], predictions: Sequence[npt.ArrayLike], *,
             options: Options | Mapping[str, Any] | None = None, gt_joints: Sequence[str],
             joint_names: Sequence[str], **metric_options: Any) -> dict[str, Any]: ...
