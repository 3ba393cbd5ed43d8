// The project's default scene (assets/scenes/ex12-2.json) as numbers, so the peers draw the same
// objects from the same place with the same light as the project's page does.
export const SCENE = {
  camera: { eye: [0, 1, 7], fovY: 70, near: 1, far: 100 },  // looking down -Z, up +Y
  light: { position: [5, 1, 7], ambient: 0.2, diffuse: 0.7, specular: 1.0, shininess: 10 },
  background: [0.4, 0.4, 0.4],
  capture: { faceSize: 256, near: 1, far: 100 },
  orbitDegreesPerSecond: 27,  // about the world Y axis
  // Model matrix T * S, then Ry(angle) where the object orbits.
  objects: [
    { name: 'ground', mesh: 'quad.obj', translate: [-1, -2, 4], scale: [100, 1, 100], colour: [0.4, 0.4, 1.0] },
    { name: 'sonic', mesh: 'sonic.obj', translate: [-2, -0.5, 2], scale: [0.05, 0.05, 0.05], colour: [0.4, 1.0, 0.4],
      orbits: true },
    { name: 'mario', mesh: 'mario.obj', translate: [2.5, -0.5, 1.5], scale: [0.02, 0.02, 0.02], colour: [1.0, 0.4, 0.4],
      orbits: true },
  ],
  // The mirror: colour = reflection * environment + base * its colour.
  mirror: { mesh: 'sphere.obj', scale: [0.5, 0.5, 0.5], colour: [0.95, 0.85, 0.4], reflection: 0.78, base: 0.3,
            centre: [0, 0.25, 0] },  // sphere.obj's centre (0, 0.5, 0) scaled: where the probe sits
};
