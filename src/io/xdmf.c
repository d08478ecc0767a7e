/* The XDMF index of the snapshots (layout in xdmf.h). Xdmf 2 as ParaView's
 * "Xdmf Reader" reads it:
 *   <Grid GridType="Collection" CollectionType="Temporal">
 *     <Grid GridType="Uniform"> <Time Value=t/>
 *       <Topology TopologyType="Polyvertex" NumberOfElements=N NodesPerElement="1"/>
 *       <Geometry GeometryType="XYZ"> N x 3 /particles/x </Geometry>
 *       <Attribute AttributeType="Scalar|Vector" Center="Node"> ... </Attribute> ...
 * Geometry is XYZ with z = 0 rather than XY over N x 2 because ParaView takes
 * only 3-component arrays as vectors (glyphs), so the snapshots store every
 * 2D vector, x included, as N x 3. With connectivity (bonds), a time step is a
 * Spatial Collection of the particle grid and a Polyline grid on the same points.
 * The field list comes from the field table (FIELD_OUTPUT), as in snapshot.c. */
#include <errno.h>
#include <stdio.h>
#include <string.h>
#include "dmhs/fields.h"
#include "dmhs/snapshot.h"
#include "dmhs/xdmf.h"
#include "dmhs/whole_file.h"
#include "h5check.h"

typedef struct {
  char file[64];
  double t;
  PetscInt64 n;
  PetscBool has_bonds;
  xdmf_connectivity bonds;
  char bonds_name[32];
} xdmf_entry;

struct xdmf {
  PetscInt n, n_alloc;
  xdmf_entry *e;
};

PetscErrorCode xdmf_create(xdmf **x) {
  PetscFunctionBeginUser;
  PetscCall(PetscNew(x));
  PetscFunctionReturn(0);
}

PetscErrorCode xdmf_destroy(xdmf **x) {
  PetscFunctionBeginUser;
  if (!*x)
    PetscFunctionReturn(0);
  PetscCall(PetscFree((*x)->e));
  PetscCall(PetscFree(*x));
  PetscFunctionReturn(0);
}

PetscErrorCode xdmf_add(xdmf *x, const char *h5_name, double t, PetscInt64 n,
                        const xdmf_connectivity *bonds) {
  PetscFunctionBeginUser;
  if (x->n == x->n_alloc) {
    xdmf_entry *grown;
    x->n_alloc = PetscMax(64, 2 * x->n_alloc);
    PetscCall(PetscMalloc1(x->n_alloc, &grown));
    if (x->n)
      PetscCall(PetscArraycpy(grown, x->e, x->n));
    PetscCall(PetscFree(x->e));
    x->e = grown;
  }
  xdmf_entry *e = &x->e[x->n++];
  PetscCall(PetscMemzero(e, sizeof(*e)));
  PetscCall(PetscStrncpy(e->file, h5_name, sizeof(e->file)));
  e->t = t;
  e->n = n;
  if (bonds) {
    e->has_bonds = PETSC_TRUE;
    e->bonds = *bonds;
    PetscCall(
        PetscStrncpy(e->bonds_name, bonds->name ? bonds->name : "bonds", sizeof(e->bonds_name)));
    e->bonds.name = NULL;
  }
  PetscFunctionReturn(0);
}

static int xdmf_data_item(FILE *f, const char *indent, PetscInt64 rows, int width,
                          const char *number_type, int precision, const char *file,
                          const char *dataset) {
  if (width > 1)
    return fprintf(f,
                   "%s<DataItem Dimensions=\"%lld %d\" NumberType=\"%s\" Precision=\"%d\" "
                   "Format=\"HDF\">%s:%s</DataItem>\n",
                   indent, (long long)rows, width, number_type, precision, file, dataset);
  return fprintf(f,
                 "%s<DataItem Dimensions=\"%lld\" NumberType=\"%s\" Precision=\"%d\" "
                 "Format=\"HDF\">%s:%s</DataItem>\n",
                 indent, (long long)rows, number_type, precision, file, dataset);
}

static int xdmf_write_particles(FILE *f, const xdmf_entry *e, const char *ind,
                                PetscBool with_time) {
  size_t nf;
  const field_desc *t = fields_table(&nf);
  const field_desc *x = fields_find("x");
  char ind2[32], ind3[32];
  int ok = 1;
  snprintf(ind2, sizeof(ind2), "%s  ", ind);
  snprintf(ind3, sizeof(ind3), "%s    ", ind);
  ok = ok && fprintf(f, "%s<Grid Name=\"particles\" GridType=\"Uniform\">\n", ind) > 0;
  if (with_time)
    ok = ok && fprintf(f, "%s<Time Value=\"%.17g\"/>\n", ind2, e->t) > 0;
  ok = ok && fprintf(f,
                     "%s<Topology TopologyType=\"Polyvertex\" NumberOfElements=\"%lld\" "
                     "NodesPerElement=\"1\"/>\n",
                     ind2, (long long)e->n) > 0;
  ok = ok && fprintf(f, "%s<Geometry GeometryType=\"XYZ\">\n", ind2) > 0;
  ok = ok && xdmf_data_item(f, ind3, e->n, snapshot_file_width(x), "Float", 8, e->file,
                            "/particles/x") > 0;
  ok = ok && fprintf(f, "%s</Geometry>\n", ind2) > 0;
  for (size_t k = 0; k < nf && ok; k++) {
    if (!(t[k].flags & FIELD_OUTPUT) || &t[k] == x)
      continue;
    const int w = snapshot_file_width(&t[k]);
    const char *number = t[k].kind == FIELD_REAL ? "Float" : "Int";
    const int precision = t[k].kind == FIELD_REAL  ? 8
                          : t[k].kind == FIELD_INT ? (int)sizeof(PetscInt)
                                                   : 8;
    char dataset[80];
    snprintf(dataset, sizeof(dataset), "/particles/%s", t[k].name);
    ok = ok && fprintf(f, "%s<Attribute Name=\"%s\" AttributeType=\"%s\" Center=\"Node\">\n", ind2,
                       t[k].name,
                       w == 1   ? "Scalar"
                       : w == 3 ? "Vector"
                                : "Matrix") > 0;
    ok = ok && xdmf_data_item(f, ind3, e->n, w, number, precision, e->file, dataset) > 0;
    ok = ok && fprintf(f, "%s</Attribute>\n", ind2) > 0;
  }
  ok = ok && fprintf(f, "%s</Grid>\n", ind) > 0;
  return ok;
}

static int xdmf_write_bonds(FILE *f, const xdmf_entry *e, const char *ind) {
  const field_desc *x = fields_find("x");
  int ok = 1;
  ok = ok && fprintf(f, "%s<Grid Name=\"%s\" GridType=\"Uniform\">\n", ind, e->bonds_name) > 0;
  ok = ok && fprintf(f,
                     "%s  <Topology TopologyType=\"Polyline\" NumberOfElements=\"%lld\" "
                     "NodesPerElement=\"%d\">\n",
                     ind, (long long)e->bonds.n_elements, e->bonds.nodes_per_element) > 0;
  ok = ok && fprintf(f,
                     "%s    <DataItem Dimensions=\"%lld %d\" NumberType=\"Int\" Precision=\"8\" "
                     "Format=\"HDF\">%s:%s</DataItem>\n",
                     ind, (long long)e->bonds.n_elements, e->bonds.nodes_per_element, e->file,
                     e->bonds.dataset) > 0;
  ok = ok && fprintf(f, "%s  </Topology>\n%s  <Geometry GeometryType=\"XYZ\">\n", ind, ind) > 0;
  ok = ok && xdmf_data_item(f, "      ", e->n, snapshot_file_width(x), "Float", 8, e->file,
                            "/particles/x") > 0;
  ok = ok && fprintf(f, "%s  </Geometry>\n%s</Grid>\n", ind, ind) > 0;
  return ok;
}

PetscErrorCode xdmf_write(const xdmf *x, const char *path) {
  whole_file w;
  PetscFunctionBeginUser;
  PetscCall(whole_file_open(&w, path, NULL));
  FILE *f = w.f;
  int ok = fprintf(f, "<?xml version=\"1.0\" ?>\n<!DOCTYPE Xdmf SYSTEM \"Xdmf.dtd\" []>\n<Xdmf "
                      "Version=\"2.0\">\n"
                      "  <Domain>\n    <Grid Name=\"dmhs\" GridType=\"Collection\" "
                      "CollectionType=\"Temporal\">\n") > 0;
  for (PetscInt k = 0; k < x->n && ok; k++) {
    const xdmf_entry *e = &x->e[k];
    if (!e->has_bonds) {
      ok = xdmf_write_particles(f, e, "      ", PETSC_TRUE);
      continue;
    }
    ok = fprintf(f,
                 "      <Grid Name=\"step\" GridType=\"Collection\" CollectionType=\"Spatial\">\n"
                 "        <Time Value=\"%.17g\"/>\n",
                 e->t) > 0;
    ok = ok && xdmf_write_particles(f, e, "        ", PETSC_FALSE);
    ok = ok && xdmf_write_bonds(f, e, "        ");
    ok = ok && fprintf(f, "      </Grid>\n") > 0;
  }
  ok = ok && fprintf(f, "    </Grid>\n  </Domain>\n</Xdmf>\n") > 0;
  PetscCall(whole_file_commit(&w, ok, NULL));
  PetscFunctionReturn(0);
}

PetscErrorCode xdmf_scan(xdmf *x, const char *dir, PetscInt n) {
  char name[64], path[PETSC_MAX_PATH_LEN];
  PetscFunctionBeginUser;
  PetscCall(h5check_quiet());
  x->n = 0;
  for (PetscInt k = 0; k < n; k++) {
    hid_t fid, attr, dset, space;
    double t;
    hsize_t dims[2];
    PetscCall(snapshot_name(k, name, sizeof(name)));
    PetscCall(PetscSNPrintf(path, sizeof(path), "%s/%s", dir, name));
    FILE *probe = fopen(path, "r");
    if (!probe)
      continue; /* deleted by the user: leave it out of the index */
    fclose(probe);
    PetscCallHDF5(path, fid = H5Fopen(path, H5F_ACC_RDONLY, H5P_DEFAULT));
    PetscCallHDF5(path, attr = H5Aopen(fid, "time", H5P_DEFAULT));
    PetscCallHDF5(path, H5Aread(attr, H5T_NATIVE_DOUBLE, &t));
    PetscCallHDF5(path, H5Aclose(attr));
    PetscCallHDF5(path, dset = H5Dopen2(fid, "/particles/x", H5P_DEFAULT));
    PetscCallHDF5(path, space = H5Dget_space(dset));
    PetscCallHDF5(path, H5Sget_simple_extent_dims(space, dims, NULL));
    PetscCallHDF5(path, H5Sclose(space));
    PetscCallHDF5(path, H5Dclose(dset));
    /* bonds, when the snapshot has them (snapshot_write_bonds) */
    xdmf_connectivity bonds = {"/bonds/rows", 0, 2, "bonds"};
    htri_t has_group, has_rows = 0;
    PetscCallHDF5(path, has_group = H5Lexists(fid, "/bonds", H5P_DEFAULT));
    if (has_group > 0)
      PetscCallHDF5(path, has_rows = H5Lexists(fid, "/bonds/rows", H5P_DEFAULT));
    if (has_rows > 0) {
      hsize_t bdims[2];
      PetscCallHDF5(path, dset = H5Dopen2(fid, "/bonds/rows", H5P_DEFAULT));
      PetscCallHDF5(path, space = H5Dget_space(dset));
      PetscCallHDF5(path, H5Sget_simple_extent_dims(space, bdims, NULL));
      PetscCallHDF5(path, H5Sclose(space));
      PetscCallHDF5(path, H5Dclose(dset));
      bonds.n_elements = (PetscInt64)bdims[0];
    }
    PetscCallHDF5(path, H5Fclose(fid));
    PetscCall(xdmf_add(x, name, t, (PetscInt64)dims[0], bonds.n_elements > 0 ? &bonds : NULL));
  }
  PetscFunctionReturn(0);
}
