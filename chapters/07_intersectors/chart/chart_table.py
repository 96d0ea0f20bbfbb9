"""Turns ch07_bench's chart benchmarks (JSON) into a table for gnuplot: one row per ray set,
layout, intersector and ISA with its Mrays/s and leak rate (percent). With repetitions, the
median is taken."""
import json
import sys

print("# rays\tlayout\tintersector\tisa\tMrays/s\tleak_percent")
with open(sys.argv[1]) as f:
    benchmarks = json.load(f)["benchmarks"]
    medians = [b for b in benchmarks if b.get("aggregate_name") == "median"]
    for b in medians or benchmarks:
        parts = b["name"].split("/")  # chart/<rays>/<layout>.<intersector>/<isa>/min_time:...
        if parts[0] != "chart":
            continue
        layout, intersector = parts[2].split(".")
        print("%s\t%s\t%s\t%s\t%.4f\t%.5f" % (parts[1], layout, intersector, parts[3], b["Mrays/s"],
                                             100.0 * b["leak_rate"]))
