"""The runs of a Google Benchmark JSON file as the book's table and chart scripts read them: when
the run was repeated, the median of each benchmark under the benchmark's own name; otherwise
every run as it is.

    sys.path.insert(0, <repository>/scripts); from gbench_json import runs"""
import json


def runs(path):
    with open(path) as f:
        benchmarks = json.load(f)["benchmarks"]
    if any(b.get("run_type") == "aggregate" for b in benchmarks):
        return [dict(b, name=b["run_name"]) for b in benchmarks if b.get("aggregate_name") == "median"]
    return benchmarks
