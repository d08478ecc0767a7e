#!/usr/bin/env python3
"""Every relative link and image of the documentation resolves.

    links.py REPO

Reads README.md, every doc/**/*.md and every bench/**/README.md; for each
Markdown link or image outside code, checks that a relative target exists
and, when it names an anchor in a Markdown page, that the page has a heading
with that anchor (GitHub's rule: lower case, punctuation but '-' and '_'
dropped, spaces to '-', repeats numbered -1, -2, ...). Prints one line per
broken link (file:line: target: why) and exits 1 if there is any.
"""
import os
import re
import sys

LINK = re.compile(r"!?\[(?:[^\[\]]|\[[^\]]*\])*\]\(\s*<?([^)\s>]+)>?(?:\s+\"[^\"]*\")?\s*\)")
HEADING = re.compile(r"^(#{1,6})\s+(.*?)\s*#*\s*$")
FENCE = re.compile(r"^\s*(```|~~~)")
CODE_SPAN = re.compile(r"(`+)(?:(?!\1).)+?\1")


def strip_code_spans(line):
    return CODE_SPAN.sub(lambda m: " " * len(m.group(0)), line)


def text_lines(path):
    """(line number, text) of the lines outside fenced code blocks."""
    inside = False
    with open(path, encoding="utf-8") as f:
        for number, line in enumerate(f, 1):
            if FENCE.match(line):
                inside = not inside
                continue
            if not inside:
                yield number, line.rstrip("\n")


def slug(heading):
    """GitHub's anchor of a heading's text."""
    text = re.sub(r"\[([^\]]*)\]\([^)]*\)", r"\1", heading)  # a link's text only
    text = re.sub(r"<[^>]+>", "", text).strip().lower()
    text = "".join(c for c in text if c.isalnum() or c in " -_")
    return text.replace(" ", "-")


def anchors(path, cache={}):
    if path not in cache:
        seen = {}
        found = set()
        for _, line in text_lines(path):
            m = HEADING.match(line)
            if not m:
                continue
            base = slug(m.group(2))
            count = seen.get(base, 0)
            seen[base] = count + 1
            found.add(base if count == 0 else f"{base}-{count}")
        for _, line in text_lines(path):  # explicit anchors: <a id="..."> or <a name="...">
            for m in re.finditer(r"<a\s+(?:id|name)=\"([^\"]+)\"", line):
                found.add(m.group(1))
        cache[path] = found
    return cache[path]


def pages(repo):
    yield os.path.join(repo, "README.md")
    for top in ("doc", "bench"):
        for root, dirs, files in os.walk(os.path.join(repo, top)):
            dirs.sort()
            for name in sorted(files):
                if name.endswith(".md") and (top == "doc" or name == "README.md"):
                    yield os.path.join(root, name)


def check(repo):
    broken = []
    for page in pages(repo):
        here = os.path.dirname(page)
        for number, line in text_lines(page):
            for m in LINK.finditer(strip_code_spans(line)):
                target = m.group(1)
                if re.match(r"^[a-z][a-z0-9+.-]*:", target):  # http:, mailto:, ...
                    continue
                path, _, anchor = target.partition("#")
                resolved = os.path.normpath(os.path.join(here, path)) if path else page
                where = f"{os.path.relpath(page, repo)}:{number}: {target}"
                if not os.path.exists(resolved):
                    broken.append(f"{where}: no such file {os.path.relpath(resolved, repo)}")
                elif not os.path.realpath(resolved).startswith(os.path.realpath(repo) + os.sep):
                    broken.append(f"{where}: outside the repository")
                elif anchor and resolved.endswith(".md") and anchor not in anchors(resolved):
                    broken.append(f"{where}: no heading with anchor #{anchor} in "
                                  f"{os.path.relpath(resolved, repo)}")
    return broken


def report(problems, failed, passed):
    """Prints each problem, then the verdict; exits 1 when there is any."""
    for line in problems:
        print(line)
    if problems:
        print(failed.format(n=len(problems)))
        sys.exit(1)
    print(passed)


def main():
    if len(sys.argv) != 2 or not os.path.isdir(sys.argv[1]):
        sys.exit("usage: links.py REPO")
    report(check(os.path.abspath(sys.argv[1])), "links: {n} broken link(s)",
           "links: every relative link and image resolves")


if __name__ == "__main__":
    main()
