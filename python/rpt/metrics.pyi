# Type stubs of rpt.metrics (see __init__.pyi).
from collections.abc import Sequence
from typing import Any, overload

import numpy.typing as npt

from . import Options, Predictions
from . import datasets

# The summary of `rpt eval --json`: on a sequence and its predictions, on lists of both, or on
# arrays per frame (persons, joints, 4) with the joints named.
@overload
def evaluate(gt: datasets.Sequence, predictions: Predictions, *, options: Options | dict[str, Any] | None = None,
             **metric_options: Any) -> dict[str, Any]: ...
@overload
def evaluate(gt: Sequence[datasets.Sequence], predictions: Sequence[Predictions], *,
             options: Options | dict[str, Any] | None = None, **metric_options: Any) -> dict[str, Any]: ...
@overload
def evaluate(gt: Sequence[npt.ArrayLike], predictions: Sequence[npt.ArrayLike], *,
             options: Options | dict[str, Any] | None = None, gt_joints: Sequence[str],
             joint_names: Sequence[str], **metric_options: Any) -> dict[str, Any]: ...
