// A static file server for the built page (no dependencies):
//   node tools/serve.mjs DIR [PORT] [--port-file FILE]
// Binds 127.0.0.1 only. Serves .wasm as application/wasm so the browser can stream-compile it.
// PORT 0 takes a free port; it is printed, and with --port-file written to FILE once listening
// (./test.sh starts the tests' server so: no port is chosen, released and bound again).
import { createServer } from 'node:http';
import { createReadStream, writeFileSync } from 'node:fs';
import { stat } from 'node:fs/promises';
import { pipeline } from 'node:stream';
import { extname, join, normalize, resolve, sep } from 'node:path';

const args = process.argv.slice(2);
const portFileAt = args.indexOf('--port-file');
const portFile = portFileAt >= 0 ? args.splice(portFileAt, 2)[1] : null;
const root = resolve(args[0] || 'build/web/site');
const port = Number(args[1] ?? process.env.PORT ?? 8080);  // the argument wins
const types = {
  '.html': 'text/html; charset=utf-8', '.js': 'text/javascript; charset=utf-8',
  '.mjs': 'text/javascript; charset=utf-8', '.css': 'text/css; charset=utf-8',
  '.wasm': 'application/wasm', '.png': 'image/png', '.json': 'application/json',
  '.obj': 'text/plain; charset=utf-8', '.svg': 'image/svg+xml',
};

const server = createServer(async (request, response) => {
  try {
    const path = decodeURIComponent(new URL(request.url, 'http://localhost').pathname);
    let file = normalize(join(root, path));
    if (file !== root && !file.startsWith(root + sep)) throw Object.assign(new Error(), { code: 'ENOENT' });
    let info = await stat(file);
    if (info.isDirectory()) {
      file = join(file, 'index.html');
      info = await stat(file);
    }
    // Streamed, as a static server does: a large model's first bytes leave at once instead of
    // after the whole file is read. The length is written out, or Node would send the body
    // chunked and the page would not know a model's size (its progress, and which models are
    // small enough to read whole).
    const body = createReadStream(file);
    await new Promise((ready, failed) => {
      body.once('open', ready);
      body.once('error', failed);
    });
    response.writeHead(200, {
      'Content-Type': types[extname(file)] || 'application/octet-stream',
      'Cache-Control': 'no-cache',
      'Content-Length': info.size,
    });
    // A read error cuts the response short (the browser sees a failed download); a browser that
    // goes away closes the file.
    pipeline(body, response, () => {});
  } catch (error) {
    response.writeHead(error.code === 'ENOENT' ? 404 : 500, { 'Content-Type': 'text/plain' });
    response.end(error.code === 'ENOENT' ? 'not found\n' : 'server error\n');
  }
});
server.listen(port, '127.0.0.1', () => {
  const { port: bound } = server.address();
  if (portFile) writeFileSync(portFile, `${bound}\n`);
  console.log(`serving ${root} at http://127.0.0.1:${bound}/`);
});
