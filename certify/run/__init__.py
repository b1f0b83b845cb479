"""Layer 4, running and reporting: certificates and shared quantities (the runner), the
report (REPORT.md, report.json), figures, plots of certified sign tables, atomic files
and progress on a terminal.  It imports every layer below it.

- :mod:`.runner`: ``@certificate``, ``@quantity``, ``conclude``, the run (serial or on
  every core).
- :mod:`.report`: outcomes in, Markdown and JSON out, and the staleness check.
- :mod:`.figures`, :mod:`.plots`: saving figures reproducibly; the certified charts.
- :mod:`.files`, :mod:`.progress`: atomic writes; progress bars on a terminal only.
"""
from . import figures, files, plots, progress, report, runner
from .figures import save_figure
from .plots import omega_figure, section5_figure, section5_name, sign_chart, spectrum_figures
from .runner import (CERTIFICATES, ERRATUM, ERRATUM_KINDS, FAIL, FALSE_STATEMENT, MISPRINT, OBSERVED, PASS,
                     REFUTED_REMARK, STATUSES, Certificate, Check, Context, Mutant, Outcome, altered, certificate, conclude,
                     load_all, observe, overridden, quantity, replaced, reset_caches, reworded, run, run_certificate, select,
                     unread)

__all__ = [
    "figures", "files", "plots", "progress", "report", "runner",
    "save_figure", "omega_figure", "section5_figure", "section5_name", "sign_chart", "spectrum_figures",
    "CERTIFICATES", "ERRATUM", "ERRATUM_KINDS", "FAIL", "FALSE_STATEMENT", "MISPRINT", "REFUTED_REMARK", "OBSERVED", "PASS", "STATUSES", "Certificate", "Check", "Context",
    "Mutant", "Outcome", "altered", "certificate", "conclude", "load_all", "observe", "quantity", "reset_caches", "run",
    "run_certificate", "select", "overridden", "replaced", "reworded", "unread",
]
