"""Coverage-guided fuzzing of one target with atheris (libFuzzer for Python).

    python tests/fuzz/fuzz.py TARGET [libFuzzer options, e.g. -max_total_time=30 -timeout=10]
    python tests/fuzz/fuzz.py --list

The seed corpus (tests/fuzz/seeds.py: the shared data, examples, generated files and every
reproducer of issue 18) is written to build/fuzz/<target>/seeds; the corpus the fuzzer grows
goes to build/fuzz/<target>/corpus, and a failing input to build/fuzz/<target>/crash-*. A
failing input is any exception other than VistrackError, a NaN or infinity in a result, a
crash or a hang (-timeout seconds on one input). Turn each into a regression test: copy it to
tests/fuzz/regressions/<target>/ (tests/python/test_fuzz_regressions.py replays them).

Coverage: vistrack's Python modules are instrumented (the scenario, plan, mission and YAML
loaders); the C++ extension is built by GCC without libFuzzer's coverage callbacks, so inside
it the search is guided by the seeds' structure and the mutations, not by coverage.
"""

from __future__ import annotations

import sys
from pathlib import Path

import atheris

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))

with atheris.instrument_imports(include=["vistrack"]):
    import targets
    from seeds import write_seeds


def main(argv: list[str]) -> None:
    if len(argv) < 2 or argv[1] not in targets.TARGETS:
        print("targets:", " ".join(targets.TARGETS))
        sys.exit(0 if len(argv) > 1 and argv[1] == "--list" else 2)
    target = targets.TARGETS[argv[1]]
    work = targets.REPO / "build" / "fuzz" / target.name
    seeds, corpus = work / "seeds", work / "corpus"
    write_seeds(target.name, seeds)
    corpus.mkdir(parents=True, exist_ok=True)
    options = [f"-max_len={target.max_len}", f"-artifact_prefix={work}/", "-timeout=20", "-rss_limit_mb=6144",
               *argv[2:], str(corpus), str(seeds)]

    def one_input(data: bytes) -> None:
        targets.check(target, data)

    atheris.Setup([argv[0], *options], one_input)
    atheris.Fuzz()


if __name__ == "__main__":
    main(sys.argv)
