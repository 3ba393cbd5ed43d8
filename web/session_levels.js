// The levels of detail of a session's meshes: built off the main thread (lod.js), never holding
// the session's job queue, and only once a frame draws them (a captured face: chunks and capture
// LOD's levels; view LOD: its levels), or when asked for all of them (demo.lodReady()).
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

  // Builds what the C++ side still lacks of what is wanted (bridge.levelJobs()): nothing, and
  // no worker, while no frame draws chunks or levels. The promise resolves when that build is done.
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

  // Resolves (to { mesh: [triangles a level] }) once nothing wanted is left to build; it asks
  // for nothing (the default page, which draws no level, starts no worker).
  async settled() {
    for (let attempt = 0; attempt < 8; ++attempt) {
      await this.done;
      if (!this.bridge.levelJobs().length) break;
      if (!this.builder.running) this.start();
    }
    return this.lodLevels;
  }

  // Asks for every level the LOD settings could draw (as native's waitForLevels), then resolves
  // once they are built: tests and the bench see the meshes as every frame could draw them.
  ready() {
    this.bridge.askForLevels();
    return this.settled();
  }
}
