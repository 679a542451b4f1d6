"""Where a run folder's tables are, for the scripts that read them (plot_run.py, the reports in
docs/results, scripts/compare_physical_columns.py). Standard library only, so that a script that
needs nothing else can import it under any Python 3.

A run's tables (summary.csv, stages.csv, history.h5, surface/, volume/) are those of the one
part its scene evaluates, parts/<part>/ (`wearsim run` and `wearsim dem` on a wear-tester case
write the sample's in parts/sample/); a folder that holds summary.csv itself (a summary folder
of docs/results, or a run of an engine that wrote its tables at the top) is its own.
"""
import glob
import os


def tables_of(run):
    """The folder of the run's tables: the run folder itself when it holds summary.csv, else
    the folder of its one part with a summary.csv, else the run folder."""
    if os.path.isfile(os.path.join(run, "summary.csv")):
        return run
    parts = sorted(glob.glob(os.path.join(run, "parts", "*", "summary.csv")))
    return os.path.dirname(parts[0]) if len(parts) == 1 else run


def run_file(run, name):
    """A file of a run folder: in the folder of its tables when it is there (summary.csv,
    stages.csv, history.h5, surface/), else in the run folder itself (parameters.prm,
    calibration.prm, checkpoint.h5, scene_series.csv)."""
    path = os.path.join(tables_of(run), name)
    return path if os.path.exists(path) else os.path.join(run, name)
