/**
 * How a surface is lit and coloured: the lights that ride with the camera
 * (key, fill, rim and a sky/ground hemisphere), the shaded materials (Phong,
 * with a little specular; the inside of an open mesh in its own colour) and
 * the reflection-lines (zebra) material. One SurfaceMaterials per view.
 */
import {
  type Camera,
  Color,
  DirectionalLight,
  DoubleSide,
  HemisphereLight,
  type Material,
  MeshPhongMaterial,
  type Quaternion,
  type Scene,
  ShaderMaterial,
  type Side,
  Vector3,
  type WebGLProgramParametersWithUniforms,
} from 'three';

/** Colours of the surface: its front, and its back where an open mesh shows its inside. */
export const SURFACE_COLORS = { front: '#8db4dc', back: '#b98b5e' } as const;

/**
 * The lights, in camera space (they turn with the view, so a model always
 * reads the same way): a key light up and to the left (the three sides of
 * a box differ), a weaker fill from the lower right that keeps the key's
 * shadow side from going flat, a rim light from behind that outlines the
 * silhouette, and a hemisphere light (sky above, darker ground below) for
 * the ambient part. `share` is the part of the surface colour each gives a
 * face turned straight at it (Lambert), as the SVG export shades too.
 */
export const LIGHTS = {
  key: { direction: new Vector3(-0.45, 0.8, 0.7).normalize(), share: 0.62 },
  fill: { direction: new Vector3(0.55, -0.5, 0.65).normalize(), share: 0.26 },
  rim: { direction: new Vector3(0.2, 0.45, -1).normalize(), share: 0.35 },
  hemisphere: { sky: '#ffffff', ground: '#a39b92', share: 0.34 },
} as const;

/**
 * Adds {@link LIGHTS} to `scene`: the directional ones to `camera` (which
 * must be in the scene), the hemisphere with its sky up the world's y axis
 * (three takes a hemisphere light's world position as the sky's direction,
 * so it cannot ride with a camera away from the origin).
 */
export function addLights(scene: Scene, camera: Camera): void {
  const { hemisphere } = LIGHTS;
  // three's lights are physical: a Lambert surface gives back intensity / π.
  const sky = new HemisphereLight(hemisphere.sky, hemisphere.ground, hemisphere.share * Math.PI);
  sky.position.set(0, 1, 0);
  scene.add(sky);
  for (const { direction, share } of [LIGHTS.key, LIGHTS.fill, LIGHTS.rim]) {
    const light = new DirectionalLight(0xffffff, share * Math.PI);
    light.position.copy(direction);
    light.target.position.set(0, 0, 0);
    camera.add(light, light.target);
  }
}

/**
 * The Lambert share of the lights for a unit normal `n` (world space) seen
 * by a camera turned by `camera`, as the shaded material gives it without
 * specular (for the SVG export's flat faces).
 */
export function lightShare(n: Vector3, camera: Quaternion): number {
  const up = (n.y + 1) / 2;
  let share = LIGHTS.hemisphere.share * (up + (1 - up) * new Color(LIGHTS.hemisphere.ground).r);
  const towards = new Vector3();
  for (const { direction, share: s } of [LIGHTS.key, LIGHTS.fill, LIGHTS.rim])
    share += s * Math.max(0, n.dot(towards.copy(direction).applyQuaternion(camera)));
  return share;
}

/**
 * Gives a shaded material the back colour: where both sides are drawn (an
 * open mesh), a fragment of a face turned away from the camera takes
 * {@link SURFACE_COLORS}.back, so the inside reads as inside.
 */
function withBackColour(shader: WebGLProgramParametersWithUniforms): void {
  shader.uniforms.backDiffuse = { value: new Color(SURFACE_COLORS.back) };
  shader.fragmentShader = shader.fragmentShader
    .replace('uniform vec3 diffuse;', 'uniform vec3 diffuse;\nuniform vec3 backDiffuse;')
    .replace(
      'vec4 diffuseColor = vec4( diffuse, opacity );',
      [
        '#ifdef DOUBLE_SIDED',
        '  vec4 diffuseColor = vec4( gl_FrontFacing ? diffuse : backDiffuse, opacity );',
        '#else',
        '  vec4 diffuseColor = vec4( diffuse, opacity );',
        '#endif',
      ].join('\n'),
    );
}

/** Stripes of the reflected environment across the zebra's view (a dark and a light band per 13° of latitude). */
export const ZEBRA_STRIPES = 14;

const ZEBRA_VERTEX = /* glsl */ `
varying vec3 vNormal;
varying vec3 vViewPosition;
void main() {
  vec4 mvPosition = modelViewMatrix * vec4( position, 1.0 );
  vViewPosition = - mvPosition.xyz;
  vNormal = normalMatrix * normal;
  gl_Position = projectionMatrix * mvPosition;
}
`;

/*
 * Reflection lines: the camera looks at the surface, which mirrors an
 * environment of horizontal bands fixed to the view (the strip lights of a
 * car maker's inspection tunnel). The band seen is a function of the
 * reflection vector, so of the normal: over a C1 surface the stripes run
 * on without a break, where the normal jumps (a C0 crease) they kink or
 * break, and where the curvature varies fast they bunch.
 */
const ZEBRA_FRAGMENT = /* glsl */ `
uniform float stripes;
varying vec3 vNormal;
varying vec3 vViewPosition;
void main() {
#ifdef FLAT_NORMALS
  vec3 n = normalize( cross( dFdx( vViewPosition ), dFdy( vViewPosition ) ) );
#else
  vec3 n = normalize( vNormal ) * ( gl_FrontFacing ? 1.0 : -1.0 );
#endif
  vec3 toEye = normalize( vViewPosition );
  vec3 r = reflect( - toEye, n );
  // Latitude of the reflected ray, 0 (straight down) to 1 (straight up).
  float s = ( asin( clamp( r.y, -1.0, 1.0 ) ) / 3.14159265 + 0.5 ) * stripes;
  // A square wave with its edges smoothed over about a pixel.
  float t = abs( fract( s ) - 0.5 ) * 2.0;
  float w = max( fwidth( s ) * 2.0, 1e-4 );
  float band = smoothstep( 0.5 - w, 0.5 + w, t );
  // A little light, so that the shape still reads between the stripes.
  float light = 0.8 + 0.2 * max( n.z, 0.0 );
  gl_FragColor = vec4( vec3( mix( 0.08, 0.96, band ) * light ), 1.0 );
}
`;

/** The view's surface materials; {@link forMode} picks one. */
export class SurfaceMaterials {
  readonly smooth: MeshPhongMaterial;
  readonly flat: MeshPhongMaterial;
  readonly zebra: ShaderMaterial;
  readonly zebraFlat: ShaderMaterial;

  constructor() {
    const shaded = {
      color: SURFACE_COLORS.front,
      specular: '#2e2e2e',
      shininess: 36,
      side: DoubleSide,
      // Push the surface back a little so polygon edges drawn at the same depth stay visible.
      polygonOffset: true,
      polygonOffsetFactor: 1,
      polygonOffsetUnits: 1,
    };
    this.smooth = new MeshPhongMaterial(shaded);
    // Flat faces without specular: a highlight would vary across a face, which should read as one colour.
    this.flat = new MeshPhongMaterial({ ...shaded, flatShading: true, specular: '#000000' });
    for (const material of [this.smooth, this.flat]) material.onBeforeCompile = withBackColour;
    const zebra = {
      uniforms: { stripes: { value: ZEBRA_STRIPES } },
      vertexShader: ZEBRA_VERTEX,
      fragmentShader: ZEBRA_FRAGMENT,
      side: DoubleSide,
      polygonOffset: true,
      polygonOffsetFactor: 1,
      polygonOffsetUnits: 1,
    };
    this.zebra = new ShaderMaterial(zebra);
    this.zebraFlat = new ShaderMaterial({ ...zebra, defines: { FLAT_NORMALS: '' } });
  }

  /** All of them, for settings every material shares. */
  get all(): Material[] {
    return [this.smooth, this.flat, this.zebra, this.zebraFlat];
  }

  /** The material of `zebra` or shaded drawing, with face normals when `flat`. */
  forMode(zebra: boolean, flat: boolean): Material {
    if (zebra) return flat ? this.zebraFlat : this.zebra;
    return flat ? this.flat : this.smooth;
  }

  /** Which faces are drawn (a shader define in three: recompiled when it changes). */
  setSide(side: Side): void {
    for (const material of this.all) {
      if (material.side === side) continue;
      material.side = side;
      material.needsUpdate = true;
    }
  }

  /** The shaded materials in their vertices' colours (on) or in the surface colour. */
  setVertexColors(on: boolean): void {
    for (const material of [this.smooth, this.flat]) {
      if (material.vertexColors === on) continue;
      material.vertexColors = on;
      material.color.set(on ? '#ffffff' : SURFACE_COLORS.front);
      material.needsUpdate = true;
    }
  }

  dispose(): void {
    for (const material of this.all) material.dispose();
  }
}
