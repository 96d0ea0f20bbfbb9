"""Chapter 16's table of frame times, from what the viewer prints after `-frames N`
("viewer: N frames, WxH, mean frame time T ms (rendering R ms), ...").

    python3 frames_table.py ch16_frames_512.txt ch16_frames_128.txt   # Markdown table"""
import re
import sys

LABELS = {512: "512 x 512 (full resolution)", 128: "128 x 128 (what a 512 x 512 window renders during a drag)"}


def main():
    print("| window | frame time | of which rendering |")
    print("|---|---:|---:|")
    for path in sys.argv[1:]:
        with open(path) as f:
            m = re.search(r"viewer: (\d+) frames, (\d+)x(\d+), mean frame time ([\d.]+) ms \(rendering ([\d.]+) ms\)", f.read())
        if not m:
            sys.exit(f"{path}: no 'viewer: ... frames' line")
        size = int(m.group(2))
        print(f"| {LABELS.get(size, f'{size} x {m.group(3)}')} | {m.group(4)} ms | {m.group(5)} ms |")


if __name__ == "__main__":
    main()
