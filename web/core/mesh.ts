import type { RuleSet } from './rule-set';

/**
 * The one mesh type that crosses between the WASM core, the worker and the
 * viewer: flat typed arrays owned by JS (copied out of the WASM heap once).
 * Face f uses faceIndices[o .. o + faceSizes[f]) where o = sum of earlier sizes.
 */
export interface Mesh {
  /** x0 y0 z0 x1 y1 z1 ... */
  positions: Float64Array;
  /** Degree of each face; polygons stay polygons. */
  faceSizes: Uint32Array;
  /** Vertex indices, face by face. */
  faceIndices: Uint32Array;
  /** Control-mesh edges kept on this mesh, as vertex index pairs (issue 4); may be empty. */
  controlEdges: Uint32Array;
  /** OpenSubdiv's tags (creases, corners, holes, border rules; issue 16); absent when the mesh has none. */
  tags?: MeshTags;
}

/** How the border of a tagged mesh is subdivided (OpenSubdiv's `t interpolateboundary` 2, 1, 0). */
export type BoundaryInterpolation = 'edge' | 'edge-and-corner' | 'none';

/** How semi-sharp creases decay from level to level (`t creasemethod normal` or `chaikin`). */
export type CreaseMethod = 'uniform' | 'chaikin';

/**
 * OpenSubdiv's tags on a mesh, as OBJ `t` lines give them (in OFF: `# t ...`
 * comments after the faces). Indices count from 0. Sharpness: 0 smooth,
 * 10 and more infinitely sharp.
 */
export interface MeshTags {
  /** Crease edges as vertex index pairs a0 b0 a1 b1 ..., each an edge of the mesh, once. */
  creaseEdges: Uint32Array;
  /** The sharpness of each crease edge (> 0). */
  creaseSharpness: Float32Array;
  /** Corner vertices, once each. */
  cornerVertices: Uint32Array;
  /** The sharpness of each corner (> 0). */
  cornerSharpness: Float32Array;
  /** Faces that are holes (ascending, once each): refined, shaping their neighbours, not drawn. */
  holes: Uint32Array;
  /** Default 'edge' (border edges sharp). */
  boundary: BoundaryInterpolation;
  /** The file had an interpolateboundary tag (written back on export). */
  boundaryGiven: boolean;
  /** Default 'uniform'. */
  creaseMethod: CreaseMethod;
  /** The file had a creasemethod tag (written back on export). */
  creaseMethodGiven: boolean;
  /** One line per tag the core read but does not apply ("line 12: tag 'smoothtriangles' is not applied"). */
  notes: string[];
}

/** OpenSubdiv's infinite sharpness: a crease or corner of 10 and above never decays. */
export const INFINITELY_SHARP = 10;

/** The formats the core reads and writes (PLY written as ASCII, STL as binary). */
export type MeshFormat = 'off' | 'obj' | 'ply' | 'stl';
/** A format to read as: one of them, or `'auto'` for the core's guess from the bytes. */
export type ReadFormat = MeshFormat | 'auto';

/** Choices when reading a file. */
export interface ReadOptions {
  /**
   * Faces turned inconsistently on an orientable surface (the error
   * `inconsistent_orientation`) are turned to agree (CGAL's polygon-soup
   * orientation); a non-orientable surface is still refused.
   */
  repairOrientation?: boolean;
}

/** CGAL's four schemes (issue 2). */
export type CgalSchemeName = 'catmull-clark' | 'loop' | 'doo-sabin' | 'sqrt3';

/** Every scheme the core knows; issue 4 adds quad-triangle, linear, linear-tri and custom (needs `rules`). */
export type SchemeName = CgalSchemeName | 'quad-triangle' | 'linear' | 'linear-tri' | 'custom';

export interface SubdivideOptions {
  scheme: SchemeName;
  /** Number of steps; 0 checks the mesh and returns it unchanged. */
  levels: number;
  /** Level of the input in the caller's history (√3 border parity). Default 0. */
  startLevel?: number;
  /** Triangulate first when the scheme needs triangles. Default false. */
  triangulate?: boolean;
  /** Memory the result may take, in bytes; 0/undefined = the module's default. */
  memoryLimitBytes?: number;
  /** quad-triangle: border vertices follow the cubic B-spline rule (true, default) or stay on the control border polygon. */
  smoothBoundary?: boolean;
  /** Overrides the mesh's `t creasemethod` tag (Catmull-Clark and Loop with tags). */
  creaseMethod?: CreaseMethod;
  /** Overrides the mesh's `t interpolateboundary` tag (Catmull-Clark and Loop with tags). */
  boundary?: BoundaryInterpolation;
  /** custom: the host and weights (rule-set.ts); required for scheme 'custom'. */
  rules?: RuleSet;
  /**
   * The caller also wants the result's render buffers ({@link subdivideForView}):
   * the memory check and prediction include them. Default false.
   */
  renderBuffers?: boolean;
  /**
   * Refine on CGAL's own hosts (Subdivision_method_3 on a Surface_mesh, the
   * reference the fast hosts are tested against) instead of the fast flat
   * tables: the same mesh, numbered alike (control edges listed in another
   * order), several times slower and larger. Tags (creases, corners, holes)
   * are the fast hosts' only: CGAL's apply none. Default false.
   */
  cgalHosts?: boolean;
}

export interface SizePrediction {
  vertices: number;
  edges: number;
  faces: number;
  /** Peak bytes the last step needs in the WASM heap. */
  peakBytes: number;
  /**
   * The limit a step is checked against: the caller's memoryLimitBytes, or
   * what the WASM heap can still take (4 GB minus what is in use, minus a margin).
   */
  memoryLimitBytes?: number;
}

/** A level as a viewer takes it: the mesh, its facts and its render buffers, from one call of the core. */
export interface LevelView {
  mesh: Mesh;
  facts: MeshFacts;
  buffers: RenderBuffers;
}

export interface MeshFacts {
  vertices: number;
  edges: number;
  faces: number;
  components: number;
  boundaries: number;
  eulerCharacteristic: number;
  genus: number;
  closed: boolean;
  triangles: number;
  quads: number;
  otherFaces: number;
  bboxMin: [number, number, number];
  bboxMax: [number, number, number];
  controlEdges: number;
}

/**
 * What the GPU draws, built by the core beside the mesh: positions and
 * normals as float32, polygons fanned into triangles, and polygon edges.
 */
export interface RenderBuffers {
  positions: Float32Array;
  /** Centre x, y, z and radius: the bounding box's centre and the largest distance from it (three.js's). */
  boundingSphere: Float32Array;
  /** Unit vertex normals: fan triangle normals weighted by area, summed (three.js's computeVertexNormals). */
  normals: Float32Array;
  /** Triangle vertex indices (3 per triangle). */
  triangles: Uint32Array;
  /**
   * Unique polygon edges as vertex index pairs, smaller index first (quads stay quads: no diagonals); on a
   * closed mesh in the order of the corners going up, otherwise ordered by the smaller index.
   */
  edges: Uint32Array;
  /** For each triangle, the polygon (face) it came from. */
  triangleFace: Uint32Array;
  /** The edges of one face only (the border), as {@link edges} gives them; empty on a closed mesh. */
  borderEdges: Uint32Array;
}
