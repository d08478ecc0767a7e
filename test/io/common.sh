# Shared by the io tests: a Poiseuille channel small enough to run 1000 steps
# in about a second (10 x 20 liquid particles on a square lattice, h = 3 dx).
QUICK=(-scene poiseuille -channel_width 1e-3 -channel_length 5e-4 -channel_nx 10 -channel_ny 20
       -sph_h 1.5e-4 -body_force 2e-4,0 -dt 2.5e-5 -output_interval 0.005 -quiet)
HERE=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)

die() { echo "FAIL: $*" >&2; exit 1; }

# Attribute of an HDF5 file's root, first element.
h5attr() { "$PY" -c "import h5py,sys; v=h5py.File(sys.argv[1],'r').attrs[sys.argv[2]]; print(v[0] if hasattr(v,'__len__') and not isinstance(v,(bytes,str)) else (v.decode() if isinstance(v,bytes) else v))" "$1" "$2"; }
