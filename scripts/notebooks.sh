#!/usr/bin/env bash
# Executes the notebooks headless with the evcxr Rust kernel, installing what is missing:
# Jupyter's minimal execution stack (nbclient, in a virtual environment) and evcxr_jupyter
# (cargo install, pinned). Executed copies go to out/notebooks/. Fails, naming the notebook and
# cell, on any cell error, compile error or panic, and when a committed notebook's stored
# outputs differ from the fresh run's (scripts/check_notebooks.py --stale): the notebooks are
# kept executed, so that they show their outputs without a run, and `--store` rewrites them.
#
# Each executed notebook is also written as HTML with its figures (out/notebooks/<name>.html),
# its mathematics typeset offline by a vendored MathJax (out/notebooks/mathjax/), and checked in
# headless Chromium (scripts/check_html.py: no unrendered TeX; screenshots in screens/).
#
# usage: scripts/notebooks.sh [NOTEBOOK.ipynb ...]   (default: notebooks/[0-9][0-9]-*.ipynb)
#        scripts/notebooks.sh --store [NOTEBOOK.ipynb ...]  executes them and stores each run's
#                                                    outputs in the notebook itself
#        scripts/notebooks.sh --site                 out/site/: the last run's notebook pages,
#                                                    cargo doc, figures and tables, one index
#        scripts/notebooks.sh --try-it NOTEBOOK.ipynb  times its Try-it edit in a live kernel
#        scripts/notebooks.sh --lab [LAB OPTIONS]    JupyterLab on notebooks/ with the same kernel,
#                                                    environment and compile cache (variables
#                                                    survive a panic there, unlike the headless run)
# env:   SPLINELAB_STATE  where the venv and compile caches are kept (default ~/.cache/splinelab)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
cd "$root"
export PATH="$HOME/.cargo/bin:$PATH"

EVCXR_VERSION=0.22.0
# MathJax for the HTML copies, vendored from the npm registry (the file's checksum pinned)
MATHJAX_VERSION=3.2.2
MATHJAX_SHA256=a4354ff94fd868aea0cc6eaaa79a57fda0588646fc46ee3700a349ee0a11cbe6
NBCLIENT_VERSION=0.11.0
NBCONVERT_VERSION=7.16.6
JUPYTERLAB_VERSION=4.4.10
CELL_TIMEOUT=1800

state="${SPLINELAB_STATE:-$HOME/.cache/splinelab}"
mkdir -p "$state"
state="$(cd "$state" && pwd)"   # evcxr needs absolute paths
venv="$state/venv"

# 1. Python: nbclient provides `jupyter execute`.
if [ ! -x "$venv/bin/jupyter-execute" ]; then
    echo "notebooks: installing nbclient $NBCLIENT_VERSION into $venv"
    python3 -m venv "$venv"
    "$venv/bin/pip" install --quiet --disable-pip-version-check "nbclient==$NBCLIENT_VERSION"
fi
if [ ! -x "$venv/bin/jupyter-nbconvert" ]; then
    echo "notebooks: installing nbconvert $NBCONVERT_VERSION into $venv"
    "$venv/bin/pip" install --quiet --disable-pip-version-check "nbconvert==$NBCONVERT_VERSION"
fi

# System packages: the mold linker (evcxr links each cell with it when it is installed, the
# kernel's largest per-cell cost after compiling) and Chromium (the check of the HTML copies).
apt_install() {
    local missing=()
    for pkg in "$@"; do dpkg -s "$pkg" >/dev/null 2>&1 || missing+=("$pkg"); done
    [ "${#missing[@]}" -eq 0 ] && return 0
    local sudo=()
    [ "$(id -u)" = 0 ] || sudo=(sudo)
    echo "notebooks: installing ${missing[*]} (apt)"
    "${sudo[@]}" env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq "${missing[@]}" >/dev/null 2>&1 ||
        { "${sudo[@]}" apt-get update -qq >/dev/null 2>&1 &&
          "${sudo[@]}" env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq "${missing[@]}" >/dev/null; }
}
if [ "${1:-}" != "--lab" ]; then
    apt_install mold chromium
else
    apt_install mold || echo "notebooks: mold not installed; evcxr links with the system linker"
fi

# MathJax, once per state folder, checked against its pinned checksum.
mathjax="$state/mathjax-$MATHJAX_VERSION"
if [ ! -f "$mathjax/tex-svg-full.js" ]; then
    echo "notebooks: fetching MathJax $MATHJAX_VERSION (npm registry)"
    tmp="$(mktemp -d)"
    (cd "$tmp" && npm pack --silent "mathjax@$MATHJAX_VERSION" >/dev/null)
    tar -xzf "$tmp/mathjax-$MATHJAX_VERSION.tgz" -C "$tmp" package/es5/tex-svg-full.js package/LICENSE
    echo "$MATHJAX_SHA256  $tmp/package/es5/tex-svg-full.js" | sha256sum --check --quiet
    mkdir -p "$mathjax"
    cp "$tmp/package/es5/tex-svg-full.js" "$tmp/package/LICENSE" "$mathjax/"
    rm -rf "$tmp"
fi

# 2. The Rust kernel.
# (evcxr_jupyter has no --version; cargo's install list names the installed version)
if ! cargo install --list | grep -q "^evcxr_jupyter v$EVCXR_VERSION:"; then
    echo "notebooks: installing evcxr_jupyter $EVCXR_VERSION (about 10 minutes)"
    CARGO_PROFILE_RELEASE_OPT_LEVEL=1 cargo install --locked --quiet evcxr_jupyter --version "$EVCXR_VERSION"
fi
export JUPYTER_PATH="$venv/share/jupyter"
export JUPYTER_DATA_DIR="$venv/share/jupyter"
evcxr_jupyter --install >/dev/null

# 3. evcxr settings (:opt 0, :cache, panics fail) and caches kept between runs.
export EVCXR_CONFIG_DIR="$root/scripts/evcxr"
export XDG_CACHE_HOME="$state/xdg-cache"
export EVCXR_TMPDIR="$state/evcxr-tmp"
mkdir -p "$XDG_CACHE_HOME" "$EVCXR_TMPDIR"
# The kernel's crate lives in $EVCXR_TMPDIR (evcxr writes its own .cargo/config.toml there);
# cargo also reads the config of every parent folder, so one in $state compiles splinelab
# itself optimised — seed 004's point searches run in seconds instead of many minutes — while
# its dependencies keep :opt 0's short compiles.
mkdir -p "$state/.cargo"
cat > "$state/.cargo/config.toml" <<'TOML'
[profile.dev.package.splinelab]
opt-level = 2
debug-assertions = false
overflow-checks = false
TOML
# The kernel dlopens code built with -C prefer-dynamic, which needs the toolchain's libstd.
# Its relative RUNPATH is computed for cargo's deps/ folder but the library is loaded from
# one level up, so under $HOME (e.g. ~/.cache/…) it points at /.rustup and dlopen fails;
# naming the folder of libstd (rustc --print target-libdir) works wherever the state lives.
export LD_LIBRARY_PATH="$(rustc --print target-libdir)${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"

# The kernel's crate resolves its dependencies offline (`:offline 1` in init.evcxr): online,
# evcxr's `cargo metadata` after the setup cell's `:dep` asks the registry again and takes
# about 2 s more of the first output. Every crate it needs is in this repository's lock file.
cargo fetch --locked --quiet

# 4. Interactive: JupyterLab with the same kernel, caches and library path; evcxr's defaults
# for panics (variables kept) instead of the headless run's.
if [ "${1:-}" = "--lab" ]; then
    if [ ! -x "$venv/bin/jupyter-lab" ]; then
        echo "notebooks: installing JupyterLab $JUPYTERLAB_VERSION into $venv"
        "$venv/bin/pip" install --quiet --disable-pip-version-check "jupyterlab==$JUPYTERLAB_VERSION"
    fi
    export EVCXR_CONFIG_DIR="$root/scripts/evcxr-lab"
    root_flag=()
    [ "$(id -u)" = 0 ] && root_flag=(--allow-root)   # containers often run as root
    exec "$venv/bin/jupyter-lab" --notebook-dir="$root/notebooks" "${root_flag[@]}" "${@:2}"
fi

# 5. The site: the notebooks' HTML copies of the last run (with MathJax and screenshots) and
# cargo doc's pages copied into out/site/, then its index written by the library
# (`splinelab site`), beside the figures and tables of the last `cargo run --release`.
if [ "${1:-}" = "--site" ]; then
    site="$root/out/site"
    mkdir -p "$site/notebooks"
    shopt -s nullglob
    pages=("$root"/out/notebooks/*.html)
    [ "${#pages[@]}" -gt 0 ] || { echo "notebooks: no HTML copies yet; run scripts/notebooks.sh first" >&2; exit 1; }
    cp "${pages[@]}" "$site/notebooks/"
    cp -r "$root/out/notebooks/mathjax" "$site/notebooks/"
    [ -d "$root/out/notebooks/screens" ] && cp -r "$root/out/notebooks/screens" "$site/notebooks/"
    cargo doc --quiet --no-deps
    rm -rf "$site/doc" && cp -r "$root/target/doc" "$site/doc"
    cargo run --quiet -- site --out "$root/out"
    exit 0
fi

# 6. The Try-it edit timed in a live kernel (scripts/notebook_times.py --try-it).
if [ "${1:-}" = "--try-it" ]; then
    paths=()
    for nb in "${@:2}"; do paths+=("$(realpath "$nb")"); done
    cd "$root/notebooks"   # the kernel's working folder, as in a notebook (`:dep path = ".."`)
    exec "$venv/bin/python" "$root/scripts/notebook_times.py" --try-it "${paths[@]}"
fi

# 7. Execute: each notebook's outputs checked against its stored ones, or stored (--store).
store=0
if [ "${1:-}" = "--store" ]; then store=1; shift; fi
if [ "$#" -gt 0 ]; then notebooks=("$@"); else notebooks=(notebooks/[0-9][0-9]-*.ipynb); fi
out="$root/out/notebooks"
mkdir -p "$out/mathjax"
cp "$mathjax/tex-svg-full.js" "$mathjax/LICENSE" "$out/mathjax/"
failed=()
for nb in "${notebooks[@]}"; do
    name="$(basename "$nb" .ipynb)"
    dir="$(dirname "$nb")"
    start=$(date +%s)
    echo "notebooks: executing $nb"
    if "$venv/bin/jupyter-execute" --kernel_name=rust --timeout="$CELL_TIMEOUT" \
        --output="${name}_executed" "$nb"; then
        mv "$dir/${name}_executed.ipynb" "$out/${name}.ipynb"
        if [ "$store" = 1 ]; then
            keep=(--store "$out/${name}.ipynb" "$nb")
        else
            keep=(--stale "$nb" "$out/${name}.ipynb")
        fi
        if "$venv/bin/python" "$root/scripts/check_notebooks.py" "$out/${name}.ipynb" &&
            "$venv/bin/python" "$root/scripts/check_notebooks.py" "${keep[@]}" &&
            "$venv/bin/jupyter-nbconvert" --to html --log-level=WARN \
                --template-file "$root/scripts/nbconvert/offline.html.j2" \
                --HTMLExporter.mathjax_url=mathjax/tex-svg-full.js "$out/${name}.ipynb"; then
            echo "notebooks: $nb ok ($(( $(date +%s) - start )) s), $out/${name}.html"
            continue
        fi
    else
        [ -f "$dir/${name}_executed.ipynb" ] && mv "$dir/${name}_executed.ipynb" "$out/${name}.ipynb"
    fi
    echo "notebooks: $nb FAILED" >&2
    failed+=("$nb")
done
if [ "${#failed[@]}" -gt 0 ]; then
    echo "notebooks: ${#failed[@]} of ${#notebooks[@]} failed: ${failed[*]}" >&2
    exit 1
fi
# 8. The HTML copies as a reader sees them: every formula rendered offline (headless Chromium),
# a screenshot of each page's first screen in out/notebooks/screens/.
python3 "$root/scripts/check_html.py" --self-test "$out/mathjax/tex-svg-full.js"
pages=()
for nb in "${notebooks[@]}"; do pages+=("$out/$(basename "$nb" .ipynb).html"); done
python3 "$root/scripts/check_html.py" --screens "$out/screens" "${pages[@]}"
echo "notebooks: ${#notebooks[@]} passed, 0 failed"
