#!/usr/bin/env python3
"""Every number the README quotes beside a link is found in the page it links to.

    readme_numbers.py REPO

For each line of README.md outside code that links to Markdown pages of the
repository (a row of its tables, a caption, a sentence), every number in the
line's own text (not in its link targets or code spans) must appear, written
the same way, in at least one of the pages the line links to: "3e-14" in the
README needs "3e-14" there, "3.1x" needs "3.1x", "0.8" needs "0.8". A number
attached to a name ("Chapter 4", "Debian 12") is a number too: the linked
page must say it as well, or the line must not link. Prints one line per
number not found and exits 1 if there is any; with -v, every number found.
"""
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from links import LINK, report, strip_code_spans, text_lines  # noqa: E402

# a number with what is written straight after it that changes its meaning:
# a factor (3x), a percentage (8 %), thousands (100k); a decimal point only
# before a digit, so that a sentence's full stop is not part of it
NUMBER = re.compile(r"(?<![\w.])(\d+(?:\.\d+)?(?:e[-+]?\d+)?)(\s?%|x\b|k\b)?")


def numbers(text):
    return {m.group(1) + (m.group(2) or "").replace(" ", "") for m in NUMBER.finditer(text)}


def page_numbers(path, cache={}):
    if path not in cache:
        with open(path, encoding="utf-8") as f:
            cache[path] = numbers(f.read())
    return cache[path]


def check(repo, verbose=False):
    missing = []
    readme = os.path.join(repo, "README.md")
    for number, line in text_lines(readme):
        bare = strip_code_spans(line)
        targets = []
        for m in LINK.finditer(bare):
            path = m.group(1).partition("#")[0]
            if path.endswith(".md") and not re.match(r"^[a-z]+:", path):
                targets.append(os.path.normpath(os.path.join(repo, path)))
        if not targets:
            continue
        text = LINK.sub(lambda m: m.group(0)[: m.group(0).index("](")], bare)  # keep link texts
        for value in sorted(numbers(text)):
            pages = [t for t in targets if os.path.exists(t) and value in page_numbers(t)]
            names = ", ".join(os.path.relpath(t, repo) for t in targets)
            if pages:
                if verbose:
                    print(f"README.md:{number}: {value} in {os.path.relpath(pages[0], repo)}")
            else:
                missing.append(f"README.md:{number}: {value} is in none of {names}")
    return missing


def main():
    args = [a for a in sys.argv[1:] if a != "-v"]
    if len(args) != 1 or not os.path.isdir(args[0]):
        sys.exit("usage: readme_numbers.py [-v] REPO")
    report(check(os.path.abspath(args[0]), "-v" in sys.argv),
           "readme_numbers: {n} number(s) of the README not found in the pages they link to",
           "readme_numbers: every number the README quotes is in the page it links to")


if __name__ == "__main__":
    main()
