"""viscoroll from Python: DMA data of a rubber -> master curve -> Prony fit -> creep spectrum ->
rolling-contact friction, one function per stage.

Each function calls the Rust library's own stage (the calls `viscoroll`'s CLI makes, through the
compiled module ``viscoroll._core``), so the numbers are the CLI's. Tables come back as pandas
DataFrames with pyvisco's column names where pyvisco has one (``f_set``, ``f``, ``E_stor``,
``E_loss``, ``T``, ``log_aT``, ``tau_i``, ``alpha_i``; ``G_...`` for shear; moduli in MPa as
pyvisco's files have them), and the chain's objects (:class:`Measurement`, :class:`MasterCurve`,
:class:`Fit`, :class:`Creep`, :class:`Run`) carry them as attributes.

Warnings of the library are issued as :class:`ViscorollWarning`; errors are raised as one
exception class per stage, each a subclass of :class:`ViscorollError`.

    >>> import viscoroll as vr
    >>> m = vr.ingest("data/pyvisco-ems-ca/freq_Eplexor_raw.xls")
    >>> fit = vr.fit(m, name="ems-ca")
    >>> vr.roll(fit, temp_c=[0, 20, 40], radius_mm=66.5, load_n_per_m=1e4, speed_m_s=4)
"""

from ._core import (
    ConvertError,
    FitError,
    IngestError,
    MapsError,
    MasterError,
    RollError,
    RunError,
    ViscorollError,
)
from ._api import (
    Creep,
    Fit,
    MasterCurve,
    Measurement,
    Run,
    ViscorollWarning,
    convert,
    fit,
    ingest,
    maps,
    master,
    roll,
    run,
    shipped_scenes,
)

__all__ = [
    "ViscorollError",
    "IngestError",
    "MasterError",
    "FitError",
    "ConvertError",
    "RollError",
    "MapsError",
    "RunError",
    "ViscorollWarning",
    "Measurement",
    "MasterCurve",
    "Fit",
    "Creep",
    "Run",
    "ingest",
    "master",
    "fit",
    "convert",
    "roll",
    "maps",
    "run",
    "shipped_scenes",
]
