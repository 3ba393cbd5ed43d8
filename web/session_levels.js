// The levels of detail of a session's meshes: built after each first frame, off the main thread
// (lod.js), never holding the session's job queue.
import { LevelBuilder } from './lod.js';

export class SessionLevels {
  // onBuilt(): new levels arrived (the session tells its listeners 'models').
  constructor(bridge, onBuilt) {
    this.bridge = bridge;
    this.onBuilt = onBuilt;
    this.builder = new LevelBuilder(bridge);
    this.lodLevels = {};  // mesh name -> [triangles a level]
    this.done = Promise.resolve({});
  }

  // Builds what the C++ side still lacks (chunks; levels while a LOD setting is on); the promise
  // resolves when that build is done.
  start() {
    this.done = this.builder.build().then((built) => {
      if (built && Object.keys(built).length) {
        this.lodLevels = { ...this.lodLevels, ...built };
        this.onBuilt();
      }
      return built;
    });
    return this.done;
  }

  // Resolves (to { mesh: [triangles a level] }) once nothing is left to build.
  async ready() {
    for (let attempt = 0; attempt < 8; ++attempt) {
      await this.done;
      if (!this.bridge.levelJobs().length) break;
      if (!this.builder.running) this.start();
    }
    return this.lodLevels;
  }
}
