"""The runs of a Google Benchmark JSON file as the book's table and chart scripts read them: when
the run was repeated, the median of each benchmark under the benchmark's own name (runs), or
every repetition without the aggregates (repetitions); otherwise every run as it is.

    sys.path.insert(0, <repository>/scripts); from gbench_json import runs"""
import json


def _benchmarks(path):
    with open(path) as f:
        return json.load(f)["benchmarks"]


def repetitions(path):
    return [b for b in _benchmarks(path) if b.get("run_type", "iteration") == "iteration"]


def runs(path):
    benchmarks = _benchmarks(path)
    if any(b.get("run_type") == "aggregate" for b in benchmarks):
        return [dict(b, name=b["run_name"]) for b in benchmarks if b.get("aggregate_name") == "median"]
    return benchmarks
