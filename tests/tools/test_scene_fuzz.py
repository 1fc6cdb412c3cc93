#!/usr/bin/python3
"""A scene fuzzer: mutations of every scene in inputs/ through `halfeti check`, each with a time limit.

Each mutation sets one number to an extreme (0, -1, 1e308, -1e308, 1e-300, .nan, .inf), a number to text or a list,
a string to a number, drops a key, misspells one, or repeats one (in the text, so the parser sees both). The answer
must be exit status 0 (a valid scene) or 2 with exactly one line on stderr that starts "halfeti: error: "; a hang
(past the time limit), a signal, status 3 or 4, or a second line is a finding and fails the test.

usage: test_scene_fuzz.py SOURCE_DIR BINARY_DIR [--per-scene N]
"""
import os
import random
import subprocess
import sys

import yaml

EXTREMES = [0, -1, 1e308, -1e308, 1e-300, float("nan"), float("inf"), "soon", [1, 2]]


def leaves(node, path=()):
    """(path, value) of every scalar leaf, and of every mapping key (for drops and misspellings)."""
    if isinstance(node, dict):
        for k, v in node.items():
            yield ("key", path + (k,), v)
            yield from leaves(v, path + (k,))
    elif isinstance(node, list):
        for i, v in enumerate(node):
            yield from leaves(v, path + (i,))
    else:
        yield ("value", path, node)


def parent_of(doc, path):
    for p in path[:-1]:
        doc = doc[p]
    return doc


def mutations(doc, text, rng, count):
    items = list(leaves(doc))
    out = []
    for _ in range(count):
        kind, path, value = rng.choice(items)
        m = yaml.safe_load(text)
        parent = parent_of(m, path)
        last = path[-1]
        if kind == "key":
            choice = rng.randrange(3)
            if choice == 0:
                del parent[last]
                out.append((f"drop {'.'.join(map(str, path))}", yaml.safe_dump(m)))
            elif choice == 1:
                parent[str(last) + "x"] = parent.pop(last)
                out.append((f"misspell {'.'.join(map(str, path))}", yaml.safe_dump(m)))
            else:
                # The key repeated in its own mapping (flow style keeps it on one line the parser reads).
                body = yaml.safe_dump(m, default_flow_style=True, width=1 << 20).strip()
                needle = f"{last}: "
                at = body.find(needle)
                if at < 0:
                    continue
                out.append((f"repeat {'.'.join(map(str, path))}", body[:at] + f"{last}: 1, " + body[at:]))
        else:
            if isinstance(value, bool):
                new = rng.choice([0, "maybe"])
            elif isinstance(value, (int, float)):
                new = rng.choice(EXTREMES)
            elif isinstance(value, str):
                new = rng.choice([0, 1e308, "", "../../x"])
            else:
                new = rng.choice(EXTREMES)
            parent[last] = new
            out.append((f"{'.'.join(map(str, path))} = {new!r}", yaml.safe_dump(m)))
    return out


def main(argv):
    source, binary = argv[1], argv[2]
    per_scene = int(argv[argv.index("--per-scene") + 1]) if "--per-scene" in argv else 20
    halfeti = os.path.join(binary, "src", "app", "halfeti")
    work = os.path.join(binary, "scene_fuzz")
    os.makedirs(work, exist_ok=True)
    rng = random.Random(20261202)  # fixed: the same mutations on every run
    scenes = []
    for folder, _, files in os.walk(os.path.join(source, "inputs")):
        if os.path.basename(folder) == "studies":
            continue  # study files, not scenes (tools_study checks their refusals)
        scenes += [os.path.join(folder, f) for f in sorted(files) if f.endswith(".yaml")]
    findings, tried, valid = [], 0, 0
    for scene in sorted(scenes):
        with open(scene) as f:
            text = f.read()
        doc = yaml.safe_load(text)
        for what, mutated in mutations(doc, text, rng, per_scene):
            # Beside the original, so that relative paths (records) resolve as they do there.
            path = os.path.join(os.path.dirname(scene), f".fuzz_{os.getpid()}.yaml")
            with open(path, "w") as f:
                f.write(mutated)
            tried += 1
            try:
                r = subprocess.run([halfeti, "check", path], capture_output=True, text=True, timeout=30)
                err = r.stderr
                lines = [l for l in err.splitlines() if l.strip()]
                if r.returncode == 0:
                    valid += 1
                elif r.returncode != 2 or len(lines) != 1 or not lines[0].startswith("halfeti: error: "):
                    findings.append(f"{os.path.basename(scene)}: {what}: status {r.returncode}: {err.strip()[:300]}")
            except subprocess.TimeoutExpired:
                findings.append(f"{os.path.basename(scene)}: {what}: no answer within 30 s")
            finally:
                os.remove(path)
    print(f"scene fuzzer: {tried} mutations of {len(scenes)} scenes: {valid} valid, {tried - valid - len(findings)} "
          f"refused with one line, {len(findings)} findings")
    for f in findings:
        print("  " + f)
    return 1 if findings else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
