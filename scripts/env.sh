# Source me: makes the plugin-enabled YADE importable from Debian's python3
# (e.g. `source scripts/env.sh && python3 -m pytest tests/python`).
_toppling_repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
_toppling_cache=${TOPPLING_CACHE:-${XDG_CACHE_HOME:-$HOME/.cache}/toppling}
export TOPPLING_REPO="$_toppling_repo"
export PYTHONPATH="$_toppling_repo/py:$_toppling_repo:$_toppling_cache/yade/lib/x86_64-linux-gnu/yade/py${PYTHONPATH:+:$PYTHONPATH}"
export PATH="/usr/bin:$PATH"
# ParaView's own Python modules, for pvbatch only (scripts/setup.sh unpacks them):
#   PYTHONPATH=$TOPPLING_PARAVIEW_PYTHON xvfb-run -a pvbatch py/pvbatch/render_series.py <run>/paraview out.png
export TOPPLING_PARAVIEW_PYTHON="$_toppling_cache/paraview/usr/lib/python3/dist-packages"
unset _toppling_repo _toppling_cache
