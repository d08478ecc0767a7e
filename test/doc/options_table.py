#!/usr/bin/python3
"""The guide's option tables, generated from what `dmhs -help` lists.

  options_table.py [--write] DMHS PAGE...

Every option table of the guide is a marker section of a page:

  <!-- options: GROUP -->
  (the table)
  <!-- end options -->

GROUP is a heading of the -help listing without its colon and without
"(not used by scene ...)", e.g. "SPH liquid (module sph)". The table shows the
group's options as -help states them: the option, its value (the default of
that listing), the unit (the description's first [...]) and the description.
Without more, the listing is the first one that uses the group: the scenes in
the order of -help's -scene line, then VARIANTS below (modules that a scene
enables only on request). A marker may join groups into one table
("GROUP + GROUP"), and may name the listings after the groups, each the
arguments of one `DMHS ARGS -help`:

  <!-- options: SPH liquid (module sph) | -scene poiseuille | -scene vein -->

then the value column gives each listing's default ("a / b", once when they
are equal; "-" where the listing does not use or list the group), headed by the
listings ("default (poiseuille / vein)"). One listing named gives its values
under "default", as the group's first listing does.

Without --write: fails (exit 1) when a marker section differs from what -help
gives now (printing the difference and the command that regenerates it), when
an option some -help lists is in no marker section, when a marker names a
group -help does not have, or when a hand-written option table (a Markdown
table outside the markers whose first header cell is "option") names an
option no -help lists. With --write: rewrites every marker section in place,
then makes the same checks.
"""
import difflib
import os
import re
import subprocess
import sys

# modules a scene enables only on request: their options are listed only then
VARIANTS = [["-scene", "vein", "-vein_clots"]]
OPTION = re.compile(r"(?<![\w-])-([a-z][a-z0-9_]*)")
ROW = re.compile(r"^  -([a-z][a-z0-9_]*) <([^>]*)> *(.*)$")
GROUP = re.compile(r"^(\S.*?)( \(not used by scene [a-z_]+\))?:$")
BEGIN = re.compile(r"^<!-- options: (.*?) -->\s*$")
END = re.compile(r"^<!-- end options -->\s*$")
UNIT = re.compile(r" ?\[([^\]\s]+)\]")


def help_text(exe, args, cache={}):
    key = tuple(args)
    if key not in cache:
        env = {k: v for k, v in os.environ.items() if not k.startswith("PETSC_OPTIONS")}
        r = subprocess.run([exe, "-skip_petscrc"] + args + ["-help"], capture_output=True,
                           text=True, env=env)
        if r.returncode != 0:
            sys.exit(f"FAIL: {exe} {' '.join(args)} -help exited with {r.returncode}:\n{r.stderr}")
        cache[key] = r.stdout
    return cache[key]


def listing(exe, args):
    """{group: (used, [(option, value, description)])} in -help's order."""
    groups, current = {}, None
    for line in help_text(exe, args).splitlines():
        m = ROW.match(line)
        if m and current is not None:
            current.append(m.groups())
            continue
        g = GROUP.match(line) if line and not line.startswith(" ") else None
        if g:
            current = []
            groups[g.group(1)] = (g.group(2) is None, current)
        else:
            current = None
    return groups


def cell(text):
    """Text as a Markdown table cell, shown as written."""
    text = text.replace("\\", "\\\\").replace("|", "\\|").replace("<", "&lt;")
    return re.sub(r"([*\[\]`])", r"\\\1", text)


def value_cell(values):
    shown = ["-" if v is None else (f"`{v}`" if v != "" else "") for v in values]
    return shown[0] if len(set(shown)) == 1 else " / ".join(shown)


def rows_of(group, listings):
    """[(option, [value per listing], description)] of one group over the listings."""
    order, rows = [], {}
    # the listings that use the group first: their order of the options
    ranked = sorted(range(len(listings)), key=lambda k: not listings[k].get(group, (False,))[0])
    for k in ranked:
        used, opts = listings[k].get(group, (False, []))
        for name, value, desc in opts:
            if name not in rows:
                order.append(name)
                rows[name] = (desc, [None] * len(listings))
            if used or len(listings) == 1:
                rows[name][1][k] = value
    return [(name, rows[name][1], rows[name][0]) for name in order]


def table(spec, exe, candidates):
    """The table a marker's spec asks for, and its options; ValueError when -help cannot give it.

    spec: GROUP[ + GROUP...][ | ARGS | ARGS...]"""
    groups, *arg_sets = [p.strip() for p in spec.split("|")]
    groups = [g.strip() for g in groups.split(" + ")]
    arg_sets = [a.split() for a in arg_sets]
    rows = []
    for group in groups:
        if arg_sets:
            listings = [listing(exe, a) for a in arg_sets]
            if not any(group in g for g in listings):
                raise ValueError(f"the -help of {' and '.join(' '.join(a) for a in arg_sets)} "
                                 f"has no group '{group}'")
        else:
            h = home(group, exe, candidates)
            if h is None:
                raise ValueError(f"no -help listing uses a group '{group}'")
            listings = [listing(exe, h)]
        rows += rows_of(group, listings)
    head = ("default" if len(arg_sets) < 2
            else f"default ({' / '.join(label(a) for a in arg_sets)})")
    out = [f"| option | {head} | unit | description |", "|---|---|---|---|"]
    for name, values, desc in rows:
        m = UNIT.search(desc)
        unit = m.group(1) if m else ""
        if m:
            desc = (desc[:m.start()] + desc[m.end():]).strip()
        out.append(f"| `-{name}` | {value_cell(values)} | {cell(unit)} | {cell(desc)} |"
                   .replace("|  |", "| |"))
    return out, [name for name, _, _ in rows]


def home(group, exe, candidates):
    """The arguments of the first listing that uses the group, or None."""
    for args in candidates:
        used, opts = listing(exe, args).get(group, (False, []))
        if used and opts:
            return args
    return None


def label(args):
    return " ".join(a for a in args if a != "-scene")


def sections(lines):
    """(begin index, end index, spec) of every marker section."""
    found, start = [], None
    for i, line in enumerate(lines):
        if BEGIN.match(line):
            if start is not None:
                raise ValueError(f"line {i + 1}: a marker inside the section of line {start + 1}")
            start = i
        elif END.match(line):
            if start is None:
                raise ValueError(f"line {i + 1}: an end marker without a start")
            found.append((start, i, BEGIN.match(lines[start]).group(1)))
            start = None
    if start is not None:
        raise ValueError(f"line {start + 1}: a marker section without its end marker")
    return found


def hand_tables(lines, inside):
    """{option: [line numbers]} from the first cells of option tables outside the markers."""
    found, in_table, is_option_table = {}, False, False
    for n, line in enumerate(lines, 1):
        if n - 1 in inside or not line.startswith("|"):
            in_table = False
            continue
        cells = [c.strip() for c in re.split(r"(?<!\\)\|", line.strip())[1:-1]]
        if not in_table:  # the header row
            in_table, is_option_table = True, bool(cells) and cells[0].lower() == "option"
            continue
        if not is_option_table or not cells or set(cells[0]) <= set("-: "):
            continue
        for span in re.findall(r"`([^`]*)`", cells[0]):
            for m in OPTION.finditer(span):
                found.setdefault(m.group(1), []).append(n)
    return found


def main():
    argv = sys.argv[1:]
    write = "--write" in argv
    argv = [a for a in argv if a != "--write"]
    if len(argv) < 2:
        sys.exit("usage: options_table.py [--write] DMHS PAGE...")
    exe, pages = argv[0], argv[1:]
    m = re.search(r"^  -scene <[^>]*> +(.*)$", help_text(exe, []), re.M)
    if not m:
        sys.exit("FAIL: -help has no -scene line")
    scenes = [s.strip() for s in m.group(1).split(",")]
    candidates = [["-scene", s] for s in scenes] + VARIANTS
    base = help_text(exe, [])
    # PETSc's own options that the listing names as not listed (and -options_file, -help)
    petsc = {"help", "options_file"} | {o.group(1) for line in base.splitlines()
                                        if not line.startswith("  -") for o in OPTION.finditer(line)}
    code = {}
    for args in candidates:
        for group, (_, opts) in listing(exe, args).items():
            for name, _, _ in opts:
                code.setdefault(name, group)

    problems, stale, tabled, unknown = [], [], set(), []
    for page in pages:
        with open(page, encoding="utf-8") as f:
            lines = f.read().split("\n")
        try:
            marks = sections(lines)
        except ValueError as e:
            problems.append(f"{page}: {e}")
            continue
        new_lines, last, inside = [], 0, set()
        for begin, end, spec in marks:
            inside.update(range(begin, end + 1))
            try:
                rendered, names = table(spec, exe, candidates)
            except ValueError as e:
                problems.append(f"{page}:{begin + 1}: {e}")
                new_lines += lines[last:end + 1]
                last = end + 1
                continue
            tabled.update(names)
            want = ["", *rendered, ""]
            have = lines[begin + 1:end]
            if have != want:
                stale.append((page, begin + 1, spec.split("|")[0].strip(), have, want))
            new_lines += lines[last:begin + 1] + want
            last = end
        new_lines += lines[last:]
        for name, where in sorted(hand_tables(lines, inside).items()):
            if name not in code and name not in petsc:
                unknown.append(f"{page}: -{name} (line {', '.join(map(str, where))})")
        if write and new_lines != lines:
            with open(page + ".tmp", "w", encoding="utf-8") as f:
                f.write("\n".join(new_lines))
            os.replace(page + ".tmp", page)
            print(f"wrote the option tables of {page}")

    print(f"{len(code)} options listed by -help over the scenes {', '.join(scenes)} "
          f"(+ {' '.join(' '.join(v) for v in VARIANTS)}); {len(tabled)} in the marker sections "
          f"of {len(pages)} page(s)")
    if stale and not write:
        for page, line, group, have, want in stale:
            print(f"FAIL: {page}:{line}: the table of {group} differs from -help:")
            sys.stdout.writelines(l + "\n" for l in difflib.unified_diff(
                have, want, f"{page} (now)", "-help", lineterm="", n=1))
        print("regenerate the tables: /usr/bin/python3 test/doc/options_table.py --write "
              f"{exe} {' '.join(pages)}")
    missing = {}
    for o in sorted(set(code) - tabled):
        missing.setdefault(code[o], []).append("-" + o)
    if missing:
        problems.append("in -help but in no option table: " + "; ".join(
            f"{' '.join(opts)} (group '{group}')" for group, opts in missing.items()))
    if unknown:
        problems.append("in a hand-written option table but registered by no scene or module: "
                        + ", ".join(unknown))
    for p in problems:
        print("FAIL: " + p)
    ok = not problems and (write or not stale)
    print("PASS" if ok else "FAIL")
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
