// The course's per-fragment Phong, written once as GLSL so both renditions do the same per-pixel
// work as the project's shaders/phong.frag: every lit object is drawn with phongMaterial(), and
// the BVH rendition shades what a reflected ray meets with the same phong().
import { GLSL3, DoubleSide, ShaderMaterial, Matrix3, Vector3 } from 'three';
import { SCENE } from './scene_facts.js';

// The uniforms every lit material shares (one object each, so one assignment reaches them all).
// `eye` is the main camera's eye also while a cube face is drawn: the course (and the project)
// light a capture as seen from the main camera, not from the probe.
export const lighting = {
  eye: { value: new Vector3(...SCENE.camera.eye) },
  lightPosition: { value: new Vector3(...SCENE.light.position) },
};

const float = (x) => x.toFixed(4);

// The Phong function with `light`'s constants (a scene file's light; the default scene's below).
export const phongGlsl = ({ ambient, diffuse, specular, shininess }) => /* glsl */`
uniform vec3 eye;
uniform vec3 lightPosition;

// Ambient and diffuse take the object's colour; white specular only where the light reaches
// the front of the surface.
vec3 phong(vec3 colour, vec3 P, vec3 N) {
  vec3 L = normalize(lightPosition - P);
  vec3 V = normalize(eye - P);
  float nDotL = max(dot(N, L), 0.0);
  vec3 c = colour * (${float(ambient)} + ${float(diffuse)} * nDotL);
  if (nDotL > 0.0) {
    vec3 R = reflect(-L, N);
    c += vec3(${float(specular)} * pow(clamp(dot(R, V), 0.0, 1.0), ${float(shininess)}));
  }
  return c;
}
`;
export const PHONG_GLSL = phongGlsl(SCENE.light);

// World position and normal for per-fragment lighting, as the project's mesh.vert. three's own
// normalMatrix is the view-space one, so the world-space normal matrix is a uniform of ours
// (set by setWorldNormalMatrix each frame; the ground's scale is not uniform).
export const WORLD_VERTEX_GLSL = /* glsl */`
uniform mat3 worldNormalMatrix;
out vec3 worldPosition;
out vec3 worldNormal;

void main() {
  vec4 world = modelMatrix * vec4(position, 1.0);
  worldPosition = world.xyz;
  worldNormal = worldNormalMatrix * normal;
  gl_Position = projectionMatrix * viewMatrix * world;
}
`;

const phongFragmentGlsl = (light) => /* glsl */`
uniform vec3 colour;
in vec3 worldPosition;
in vec3 worldNormal;
out vec4 fragColour;
${phongGlsl(light)}
void main() {
  fragColour = vec4(phong(colour, worldPosition, normalize(worldNormal)), 1.0);
}
`;

// A material of the shared program (three compiles one program for equal sources) with the
// object's own colour and normal matrix; `light` a scene file's (the default scene's if absent).
export function phongMaterial(colour, light = SCENE.light) {
  return worldMaterial(phongFragmentGlsl(light), { colour: { value: new Vector3(...colour) } });
}

// A GLSL3 ShaderMaterial over WORLD_VERTEX_GLSL, lit by the shared uniforms; both sides drawn,
// as the project draws without face culling.
export function worldMaterial(fragmentShader, uniforms) {
  return new ShaderMaterial({
    glslVersion: GLSL3,
    side: DoubleSide,
    vertexShader: WORLD_VERTEX_GLSL,
    fragmentShader,
    uniforms: { ...lighting, worldNormalMatrix: { value: new Matrix3() }, ...uniforms },
  });
}

export function setWorldNormalMatrix(mesh) {
  // three's own materials (the frosted peer's glass) take their normals from three.
  if (!mesh.material.uniforms?.worldNormalMatrix) return;
  mesh.material.uniforms.worldNormalMatrix.value.getNormalMatrix(mesh.matrixWorld);
}
