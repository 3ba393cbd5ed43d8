// Rendition B: no cube map. Each Phong mesh gets a three-mesh-bvh MeshBVH, packed into textures
// (MeshBVHUniformStruct, and its vertex normals in a FloatVertexAttributeTexture), and the
// sphere's fragment shader traces its reflected view ray against every mesh with the library's
// bvhIntersectFirstHit, keeps the nearest hit and shades it with the same Phong as the raster
// pass; a ray that meets nothing sees the clear colour.
import { Matrix3, Matrix4, Vector3 } from 'three';
import { BVHShaderGLSL, FloatVertexAttributeTexture, MeshBVH, MeshBVHUniformStruct } from 'three-mesh-bvh';
import { PHONG_GLSL, worldMaterial } from './phong.js';
import { startPeer } from './peer_page.js';
import { SCENE } from './scene_facts.js';

const { mirror, background } = SCENE;
const vec3 = (v) => `vec3(${v.map((x) => x.toFixed(4)).join(', ')})`;

// One set of uniforms a traced mesh: its BVH, normals, inverse model matrix, world normal matrix
// and colour (bvhI, normalsI, inverseModelI, normalMatrixI, colourI).
const traced = SCENE.objects.map((fact) => ({
  bvh: new MeshBVHUniformStruct(),
  normals: new FloatVertexAttributeTexture(),
  inverseModel: new Matrix4(),
  normalMatrix: new Matrix3(),
  colour: new Vector3(...fact.colour),
}));

const MIRROR_FRAGMENT_GLSL = /* glsl */`
${BVHShaderGLSL.common_functions}
${BVHShaderGLSL.bvh_struct_definitions}
${BVHShaderGLSL.bvh_ray_functions}
${PHONG_GLSL}
${traced.map((_, i) => `uniform BVH bvh${i};
uniform sampler2D normals${i};
uniform mat4 inverseModel${i};
uniform mat3 normalMatrix${i};
uniform vec3 colour${i};`).join('\n')}
uniform vec3 baseColour;
in vec3 worldPosition;
in vec3 worldNormal;
out vec4 fragColour;

// Keeps the hit of origin + t * direction with one mesh if it is nearer than \`nearest\`. The ray
// goes into the mesh's space unnormalised, so t is the same parameter in both spaces.
void traceMesh(BVH bvh, sampler2D normals, mat4 inverseModel, mat3 normalMatrix, vec3 colour,
               vec3 origin, vec3 direction, inout float nearest, inout vec3 hitNormal, inout vec3 hitColour) {
  vec3 o = (inverseModel * vec4(origin, 1.0)).xyz;
  vec3 d = mat3(inverseModel) * direction;
  uvec4 faceIndices = uvec4(0u);
  vec3 faceNormal = vec3(0.0), barycoord = vec3(0.0);
  float side = 1.0, dist = INFINITY;
  if (bvhIntersectFirstHit(bvh, o, d, faceIndices, faceNormal, barycoord, side, dist) && dist < nearest) {
    nearest = dist;
    hitNormal = normalize(normalMatrix * textureSampleBarycoord(normals, barycoord, faceIndices.xyz).xyz);
    hitColour = colour;
  }
}

void main() {
  vec3 N = normalize(worldNormal);
  vec3 I = normalize(worldPosition - eye);
  vec3 R = reflect(I, N);
  float nearest = INFINITY;
  vec3 hitNormal = vec3(0.0), hitColour = vec3(0.0);
${traced.map((_, i) => `  traceMesh(bvh${i}, normals${i}, inverseModel${i}, normalMatrix${i}, colour${i}, worldPosition, R, nearest, hitNormal, hitColour);`).join('\n')}
  vec3 reflected = nearest < INFINITY ? phong(hitColour, worldPosition + nearest * R, hitNormal) : ${vec3(background)};
  fragColour = vec4(${mirror.reflection.toFixed(4)} * reflected + ${mirror.base.toFixed(4)} * baseColour, 1.0);
}
`;

const uniforms = { baseColour: { value: new Vector3(...mirror.colour) } };
traced.forEach((t, i) => {
  uniforms[`bvh${i}`] = { value: t.bvh };
  uniforms[`normals${i}`] = { value: t.normals };
  uniforms[`inverseModel${i}`] = { value: t.inverseModel };
  uniforms[`normalMatrix${i}`] = { value: t.normalMatrix };
  uniforms[`colour${i}`] = { value: t.colour };
});
const mirrorMaterial = worldMaterial(MIRROR_FRAGMENT_GLSL, uniforms);

startPeer({
  mirrorMaterial,
  makeRendition({ renderer, world }) {
    // Built once: the meshes never change shape, only their model matrices do. (MeshBVH
    // reorders the geometry's index in place; the triangles drawn stay the same.)
    world.objects.forEach((mesh, i) => {
      traced[i].bvh.updateFrom(new MeshBVH(mesh.geometry));
      traced[i].normals.updateFrom(mesh.geometry.getAttribute('normal'));
    });
    return {
      draw() {
        world.objects.forEach((mesh, i) => {
          traced[i].inverseModel.copy(mesh.matrixWorld).invert();
          traced[i].normalMatrix.getNormalMatrix(mesh.matrixWorld);
        });
        renderer.render(world.scene, world.camera);
      },
    };
  },
});
