import type { Sample } from '../ui/gallery';

/** The gallery's sample meshes, served from public/meshes/ (CGAL's are extracted there at set-up). */
export const SAMPLES: readonly Sample[] = [
  { id: 'cube', path: 'meshes/cube.off', label: 'Cube', note: '6 quads, closed' },
  {
    id: 'cube-creased',
    path: 'meshes/cube-creased.obj',
    label: 'Creased cube',
    note: 'sharp, semi-sharp and fading edges, a corner',
  },
  { id: 'tetrahedron', path: 'meshes/tetrahedron.off', label: 'Tetrahedron', note: '4 triangles, closed' },
  { id: 'octahedron', path: 'meshes/octahedron.off', label: 'Octahedron', note: '8 triangles, closed' },
  { id: 'icosahedron', path: 'meshes/icosahedron.off', label: 'Icosahedron', note: '20 triangles, closed' },
  { id: 'torus', path: 'meshes/torus.off', label: 'Torus', note: 'quads, genus 1' },
  { id: 'open-grid', path: 'meshes/open-grid.off', label: 'Open grid', note: 'quads with a boundary' },
  {
    id: 'rhombicuboctahedron',
    path: 'meshes/rhombicuboctahedron.off',
    label: 'Rhombicuboctahedron',
    note: '8 triangles + 18 quads',
  },
  {
    id: 'triacontahedron',
    path: 'meshes/triacontahedron.off',
    label: 'Rhombic triacontahedron',
    note: '30 quads; corners of valence 3 and 5',
  },
  {
    id: 'pentagonal-tower',
    path: 'meshes/pentagonal-tower.off',
    label: 'Pentagonal tower',
    note: 'a pentagon, 5 quads, 5 triangles',
  },
  { id: 'saddle', path: 'meshes/saddle.off', label: 'Saddle', note: 'open, not planar: z = (x² − y²)/2' },
  { id: 'mannequin', path: 'meshes/cgal/mannequin-devil.off', label: 'Mannequin (CGAL)', note: 'real scan, triangles' },
  { id: 'elephant', path: 'meshes/cgal/elephant.off', label: 'Elephant (CGAL)', note: 'real model, triangles' },
  { id: 'fandisk', path: 'meshes/cgal/fandisk.off', label: 'Fandisk (CGAL)', note: 'CAD part, triangles' },
  { id: 'holes', path: 'meshes/cgal/holes.off', label: 'Holes (CGAL)', note: 'triangles with boundaries' },
];
