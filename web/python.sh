# Sourced by test.sh and bench.sh: the venv with GEOS (shapely 2.2.0) that the differential tests and the layer
# benchmark compare against, made at .venv when missing (each step does nothing when already done).
if [ ! -x .venv/bin/python ]; then
  python3 -m venv .venv || {
    sudo=""; [ "$(id -u)" -ne 0 ] && sudo=sudo
    $sudo apt-get install -y -qq python3-venv && python3 -m venv .venv
  }
fi
.venv/bin/python -c 'import shapely, sys; sys.exit(shapely.__version__ != "2.2.0")' 2>/dev/null \
  || .venv/bin/pip install --quiet shapely==2.2.0
