// Chunks and levels of detail, built off the main thread. Chunking a 150k-triangle figure and
// simplifying it would hold the page for a long while, so after the first frame the page asks the
// C++ side what is left to build (bridge.levelJobs(): a mesh's chunks and coarser levels, once a
// frame draws them), and a Web Worker (lod_worker.js) builds it with the same C++ as the
// native build (core's buildLevels, compiled into the worker's own wasm module): the same chunk
// order and the same levels. The results come back to the main thread one piece a task (level 0
// in chunk order, then each coarser level, then "done"), so frames, input, scene switches and
// dropped files go on in between.
//
// This module imports nothing: the page's session_levels.js uses it.

const nextTask = () => new Promise((resolve) => setTimeout(resolve, 0));

// Builds what the C++ side asks for, one build at a time; a new scene cancels the one under way.
export class LevelBuilder {
  constructor(bridge) {
    this.bridge = bridge;
    this.generation = 0;
    this.worker = null;
    this.running = null;  // the build under way (a promise), or null
    this.longestHandOffMs = 0;  // the longest main-thread task that handed a piece in
    this.events = [];  // 'start', 'done' with times (performance.now()), for tests and tools
    this.gate = null;  // while held: a promise the built pieces wait on
    this.waiting = 0;  // the worker's answers waiting at the gate
  }

  // A test hook (demo.holdLevels): while held, the worker's answers wait before they are handed
  // in, so a test acts in the state "first frame drawn, levels not in" without racing the worker.
  hold(on) {
    if (on && !this.gate) {
      let open;
      this.gate = { promise: new Promise((resolve) => { open = resolve; }), open };
    } else if (!on) {
      this.gate?.open();
      this.gate = null;
    }
  }

  // Stops the build under way (its results are dropped) and ends its worker.
  cancel() {
    ++this.generation;
    this.worker?.terminate();
    this.worker = null;
    this.running = null;
  }

  // Starts a build of what is left (if none is under way) and resolves when it is done, with
  // { name: [triangles of level 0, 1, ...] } for the meshes it gave levels to (null if cancelled).
  build() {
    if (!this.running) {
      const generation = this.generation;
      this.running = this.run(generation).finally(() => {
        if (generation === this.generation) this.running = null;
      });
    }
    return this.running;
  }

  // Starts a worker and posts it every job at once; it works through them while the page draws,
  // and each answer comes back as a task of its own. Returns [{ job, triangles, answer }] (null
  // for a mesh that has gone); without a worker each answer is an error and the meshes stay whole.
  postJobs(jobs, settings) {
    const { bridge } = this;
    let worker = null;
    try {
      worker = new Worker(new URL('./lod_worker.js', import.meta.url), { type: 'module' });
      this.worker = worker;
    } catch (e) {
      console.warn(`levels of detail: no worker (${e.message}); meshes stay whole`);
    }
    const answers = new Map();
    if (worker) {
      worker.onmessage = ({ data }) => answers.get(data.id)?.resolve(data);
      worker.onerror = (e) => {
        for (const a of answers.values()) a.resolve({ error: e.message || 'the worker failed' });
      };
    }
    const work = jobs.map((job, id) => {
      const base = bridge.meshLevelZero(job.name);
      if (!base) return null;
      const triangles = base.indices.length / 3;
      if (!worker) return { job, triangles, answer: Promise.resolve({ error: 'no worker' }) };
      const answer = new Promise((resolve) => answers.set(id, { resolve }));
      worker.postMessage({ id, positions: base.positions, vertexFloats: base.vertexFloats, indices: base.indices,
                           chunks: job.chunks, coarser: job.coarser, settings },
                         [base.positions.buffer, base.indices.buffer]);
      return { job, triangles, answer };
    });
    return { worker, work };
  }

  async run(generation) {
    const { bridge } = this;
    const jobs = bridge.levelJobs();
    if (!jobs.length) return {};
    this.events.push({ event: 'start', at: performance.now(), jobs: jobs.length });
    const { worker, work } = this.postJobs(jobs, bridge.lodSettings());
    // Each piece handed in is a short main-thread task; after a long one the page gets a turn.
    let since = performance.now();
    const handOff = async (call) => {
      const start = performance.now();
      const error = call();
      const end = performance.now();
      this.longestHandOffMs = Math.max(this.longestHandOffMs, end - start);
      if (end - since > 8) {
        await nextTask();
        since = performance.now();
      }
      return error;
    };
    const built = {};
    for (const item of work) {
      if (!item) continue;
      const result = await item.answer;
      while (this.gate) {
        ++this.waiting;
        await this.gate.promise.finally(() => { --this.waiting; });
      }
      since = performance.now();  // a new task
      if (generation !== this.generation) return null;
      const { job, triangles } = item;
      const { name, revision } = job;
      if (result.error) console.warn(`levels of detail of ${name}: ${result.error}; drawn whole`);
      if (job.chunks) {
        // Without a result, the mesh is one chunk: culled whole, as before it had chunks.
        const chunks = result.chunks ||
          { indices: bridge.meshLevelZero(name)?.indices || new Uint32Array(0), counts: [triangles] };
        const error = await handOff(() => bridge.setMeshChunks({ name, revision, indices: chunks.indices, chunkTriangles: chunks.counts }));
        if (error) console.warn(`chunks of ${name}: ${error}`);
      }
      if (job.coarser) {
        const levelTriangles = [triangles];
        for (const level of result.levels || []) {
          if (generation !== this.generation) return null;
          const error = await handOff(() => bridge.addLod({ name, revision, indices: level.indices, chunkTriangles: level.counts }));
          if (error) {
            console.warn(`capture LOD of ${name}: ${error}`);
            break;
          }
          levelTriangles.push(level.indices.length / 3);
        }
        if (generation !== this.generation) return null;
        bridge.finishLevels({ name, revision });
        built[name] = levelTriangles;
      }
    }
    worker?.terminate();  // its memory (the worker module's wasm heap) goes with it
    if (this.worker === worker) this.worker = null;
    this.events.push({ event: 'done', at: performance.now() });
    const summary = Object.entries(built).map(([n, t]) => `${n} ${t.join(' > ')}`).join(', ');
    if (Object.keys(built).length) console.info(`capture LOD levels (triangles): ${summary}`);
    return built;
  }
}
