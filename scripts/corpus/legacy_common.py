"""Shared bits of the legacy-GL gatherers: the mirror helpers of effectc's scripts/corpus and
the compatibility-profile filter (every stage without #version, or #version <= 150, or
`#version N compatibility`)."""
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mirror import Mirror, write_program, strip_cpp_comments, c_string, C_LITERAL  # noqa: E402,F401

_VERSION = re.compile(r"^[ \t]*#[ \t]*version[ \t]+(\d+)[ \t]*(\w*)", re.M)


def _no_comments(text):
    return re.sub(r"/\*.*?\*/|//[^\n]*", " ", text, flags=re.S)


def legacy_stage(text):
    m = _VERSION.search(_no_comments(text))
    if not m:
        return True
    return int(m.group(1)) <= 150 or m.group(2) == "compatibility"


def legacy_program(stages):
    """stages: list of (stage, stem, text)."""
    return all(legacy_stage(t) for _, _, t in stages)


class Writer:
    """Writes programs once each (by content), only compatibility-profile ones."""

    def __init__(self, out, source):
        self.out, self.source, self.seen, self.names = out, source, set(), set()
        self.written = self.skipped_version = self.dups = 0

    def add(self, name, stages):
        key = tuple((s, t) for s, _, t in stages)
        if key in self.seen:
            self.dups += 1
            return
        self.seen.add(key)
        if not legacy_program(stages):
            self.skipped_version += 1
            return
        base, k = name, 2
        while name in self.names:
            name, k = f"{base}.{k}", k + 1
        self.names.add(name)
        write_program(self.out, self.source, name, stages)
        self.written += 1

    def report(self):
        print(f"{self.source}: {self.written} programs written, {self.dups} duplicates, "
              f"{self.skipped_version} skipped (#version > 150, not compatibility)")
