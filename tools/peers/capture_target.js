// The cube every peer's CubeCamera draws a probe into, as the project's capture: RGBA8, linear
// filtering, no mipmaps, a depth buffer; `size` pixels a face.
import { LinearFilter, RGBAFormat, UnsignedByteType, WebGLCubeRenderTarget } from 'three';

export const captureTarget = (size) => new WebGLCubeRenderTarget(size, {
  format: RGBAFormat, type: UnsignedByteType, minFilter: LinearFilter, magFilter: LinearFilter,
  generateMipmaps: false, depthBuffer: true,
});
