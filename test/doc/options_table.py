#!/usr/bin/python3
"""The user guide's option tables against the options dmhs registers.

  options_table.py DMHS PAGE...

Runs `DMHS -scene S -help` for every scene that `-help` names on its -scene
line (and the variants that enable a module only on request, VARIANTS below),
collects every option the listings show (lines '  -name <value> ...'), and
collects the options the guide's pages document: the first cell of every row
of their option tables (Markdown tables whose first header cell is "option"), every
`-name` in backticks there. Fails (exit 1), naming them, when
 * an option that -help lists is in no option table,
 * an option table lists an option that no -help listing shows (PETSc's own
   options that -help names as not listed, e.g. -log_view, are allowed),
 * the `-scene` row does not name every scene.
"""
import re
import subprocess
import sys

# modules a scene enables only on request: their options are listed only then
VARIANTS = [["-scene", "vein", "-vein_clots"]]
OPTION = re.compile(r"(?<![\w-])-([a-z][a-z0-9_]*)")


def help_text(exe, args):
    r = subprocess.run([exe] + args + ["-help"], capture_output=True, text=True)
    if r.returncode != 0:
        sys.exit(f"FAIL: {exe} {' '.join(args)} -help exited with {r.returncode}:\n{r.stderr}")
    return r.stdout


def listed(text):
    return {m.group(1) for m in re.finditer(r"^  -([a-z][a-z0-9_]*) <", text, re.M)}


def documented(path):
    """{option: [line numbers]} from the first cells of the option tables, and the -scene row."""
    found, scene_row = {}, None
    in_table, is_option_table = False, False
    with open(path) as f:
        for n, line in enumerate(f, 1):
            if not line.startswith("|"):
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
                    if m.group(1) == "scene" and scene_row is None:
                        scene_row = " ".join(cells[1:])
    return found, scene_row


def main():
    if len(sys.argv) < 3:
        sys.exit("usage: options_table.py DMHS PAGE...")
    exe, pages = sys.argv[1], sys.argv[2:]
    guide = " ".join(pages)
    base = help_text(exe, [])
    m = re.search(r"^  -scene <[^>]*> +(.*)$", base, re.M)
    if not m:
        sys.exit("FAIL: -help has no -scene line")
    scenes = [s.strip() for s in m.group(1).split(",")]
    # PETSc's own options that the listing names as not listed (and -options_file, -help)
    petsc = {"help", "options_file"} | {o.group(1) for line in base.splitlines()
                                        if not line.startswith("  -") for o in OPTION.finditer(line)}
    code = set()
    for args in [["-scene", s] for s in scenes] + VARIANTS:
        got = listed(help_text(exe, args))
        if not got:
            sys.exit(f"FAIL: {' '.join(args)} -help lists no option")
        code |= got
    doc, scene_row = {}, None
    for page in pages:
        found, row = documented(page)
        for o, lines in found.items():
            doc.setdefault(o, []).extend(f"{page}:{n}" for n in lines)
        scene_row = scene_row or row
    missing = sorted(code - set(doc))
    unknown = sorted(o for o in set(doc) - code if o not in petsc)
    ok = True
    print(f"{len(code)} options listed by -help over the scenes {', '.join(scenes)} "
          f"(+ {' '.join(' '.join(v) for v in VARIANTS)}); {len(doc)} in the option tables of {guide}")
    if missing:
        ok = False
        print(f"FAIL: in -help but in no option table of {guide}: " + " ".join("-" + o for o in missing))
    if unknown:
        ok = False
        print(f"FAIL: in an option table of {guide} but registered by no scene or module: "
              + ", ".join(f"-{o} ({', '.join(doc[o])})" for o in unknown))
    if scene_row is None:
        ok = False
        print(f"FAIL: {guide} has no -scene row")
    else:
        absent = [s for s in scenes if f"`{s}`" not in scene_row]
        if absent:
            ok = False
            print(f"FAIL: the -scene row of {guide} does not name the scenes " + ", ".join(absent))
    print("PASS" if ok else "FAIL")
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
