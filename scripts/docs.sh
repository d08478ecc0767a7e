#!/usr/bin/env bash
# Builds the documentation as a site with MkDocs: README.md as the front page,
# doc/ and the results' READMEs under bench/, every page as in the repository
# (links between them work unchanged). Installs MkDocs when missing (Debian:
# mkdocs, python3-pymdownx for GitHub's heading anchors).
#   scripts/docs.sh                 build into build/site/ (open build/site/index.html)
#   scripts/docs.sh --out DIR       build into DIR
#   scripts/docs.sh --serve         serve at http://127.0.0.1:8000 while editing
# Strict: a page link MkDocs cannot resolve fails the build. Anchors and images
# are checked by ctest doc_links (test/doc/links.py).
set -euo pipefail
repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
out="${DMHS_BUILD_DIR:-$repo/build}/site" serve=0
while [ $# -gt 0 ]; do
  case "$1" in
    --out) out="${2:?--out needs a directory}"; shift 2 ;;
    --serve) serve=1; shift ;;
    -h|--help) sed -n '2,/^set -euo/p' "$0" | sed '$d; s/^# \{0,1\}//'; exit 0 ;;
    *) echo "docs: unknown argument '$1' (see --help)" >&2; exit 2 ;;
  esac
done

"$repo/scripts/debian_packages.sh" docs mkdocs python3-pymdownx

# The site's sources: the README as index.md beside doc/ and the results'
# pages, so that every relative link of the repository stays valid.
stage="$(mktemp -d)"
trap 'rm -rf "$stage"' EXIT
cp "$repo/README.md" "$stage/index.md"
cp -r "$repo/doc" "$stage/doc"
(cd "$repo" && find bench -name README.md -o -name '*.csv') | while read -r f; do
  mkdir -p "$stage/$(dirname "$f")" && cp "$repo/$f" "$stage/$f"
done
cat > "$stage/mkdocs.yml" <<EOF
site_name: dmhs
site_description: SPH liquid coupled to mass-spring solids in soft biological conduits
docs_dir: pages
site_dir: $out
use_directory_urls: false
strict: true
theme: readthedocs
markdown_extensions:
  - tables
  - toc:
      permalink: true
      slugify: !!python/object/apply:pymdownx.slugs.slugify {kwds: {case: lower}}
nav:
  - Home: index.md
  - User guide:
      - Contents: doc/user-guide.md
      - Building and running: doc/guide/running.md
      - Options: doc/guide/options.md
      - Channels and the box: doc/guide/channels.md
      - Solids, cantilever, flap: doc/guide/solids.md
      - Intestine: doc/guide/scene-intestine.md
      - Vein: doc/guide/scene-vein.md
      - Clots: doc/guide/clots.md
      - Output, checkpoints, restart: doc/guide/output.md
      - Errors: doc/guide/errors.md
  - Reproducing the thesis: doc/reproduction.md
  - Cases: doc/cases.md
  - Validation: doc/validation.md
  - Performance: doc/performance.md
  - For LAMMPS users: doc/lammps.md
  - Theory: doc/theory.md
  - Stability: doc/stability.md
  - Parallel: doc/parallel.md
  - Architecture: doc/architecture.md
  - Install: doc/install.md
  - Cluster: doc/cluster.md
EOF
mkdir "$stage/pages"
mv "$stage/index.md" "$stage/doc" "$stage/pages/"
[ -d "$stage/bench" ] && mv "$stage/bench" "$stage/pages/"
cd "$stage"
if [ "$serve" -eq 1 ]; then
  exec mkdocs serve
fi
mkdocs build --quiet --clean
echo "docs: the site is in $out (open $out/index.html)"
