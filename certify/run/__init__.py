"""Layer 4, running and reporting: certificates and shared quantities (the runner), the
report (REPORT.md, report.json), figures, plots of certified sign tables, atomic files
and progress on a terminal.  It imports every layer below it.

- :mod:`.runner`: ``@certificate``, ``@quantity``, ``conclude``, the run (serial or on
  every core).
- :mod:`.report`: outcomes in, Markdown and JSON out, and the staleness check.
- :mod:`.checks`: checks several proofs make alike (printed digits, root counts, eliminants,
  identities, corrections one for one), and the witnesses they give the kernel.
- :mod:`.saving`, :mod:`.plots`: saving figures reproducibly; the certified charts.
- :mod:`.files`, :mod:`.progress`: atomic writes, the committed findings; progress bars on a
  terminal only.
- :mod:`.identify`, :mod:`.section5_orbits`: the periodic words of simulated orbits, certified;
  the committed findings of Section 5 (reports/section5-orbits.json) and their explanations.
"""
from certify.caches import for_a_run  # the memo of a run, for the proofs' shared steps
from certify.witnesses import captured, witnesses_of

from . import checks, files, plots, progress, report, runner, saving
from .census_report import committed_windows
from .checks import (
                     check_of,
                     combined,
                     concluded,
                     count_check,
                     digits_check,
                     eliminant_check,
                     identity,
                     kept_witnesses,
                     result_check,
                     witness,
)
from .files import first_member, load_findings, read_first_member
from .island_figures import report_figure as island_figure
from .plots import omega_figure, section5_figure, section5_name, sign_chart, spectrum_figures
from .runner import (
                     CERTIFICATES,
                     ERRATUM,
                     ERRATUM_KINDS,
                     EXPLANATION,
                     FAIL,
                     FALSE_STATEMENT,
                     MISPRINT,
                     OBSERVED,
                     PASS,
                     REFUTED_REMARK,
                     STATUSES,
                     Certificate,
                     Check,
                     Context,
                     Mutant,
                     Outcome,
                     altered,
                     certificate,
                     committed,
                     conclude,
                     load_all,
                     named,
                     observe,
                     overridden,
                     quantity,
                     replaced,
                     reset_caches,
                     reworded,
                     run_certificate,
                     run_selected,
                     select,
                     unread,
)
from .saving import save_figure
from .section5_orbits import explanations

__all__ = [
    "checks", "files", "plots", "progress", "report", "runner", "saving",
    "check_of", "combined", "concluded", "count_check", "witness", "digits_check", "eliminant_check", "identity",
    "result_check", "kept_witnesses", "captured", "witnesses_of",
    "first_member", "read_first_member", "load_findings",
    "committed_windows", "island_figure", "explanations", "save_figure",
    "omega_figure", "section5_figure", "section5_name", "sign_chart",
    "spectrum_figures",
    "CERTIFICATES", "EXPLANATION", "ERRATUM", "ERRATUM_KINDS", "FAIL", "FALSE_STATEMENT", "MISPRINT", "REFUTED_REMARK",
    "OBSERVED",
    "PASS", "STATUSES", "Certificate", "Check", "Context",
    "Mutant", "Outcome", "altered", "certificate", "committed", "conclude", "load_all", "named", "observe", "quantity",
    "reset_caches", "for_a_run",
    "run_selected",
    "run_certificate", "select", "overridden", "replaced", "reworded", "unread",
]
