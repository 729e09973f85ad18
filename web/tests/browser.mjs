// Headless Chromium driven over the DevTools protocol (a pipe: no npm package, no port) and PNG
// helpers: what the browser tests and the web benchmark share. The pages come from
// web/static_server.mjs, the server `./run.sh web` gives a student.
import { spawn } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import zlib from 'node:zlib';

// Chromium, headless, WebGL 2 through SwiftShader; `extraFlags` e.g. '--disable-webgl2'.
export async function launch(extraFlags = []) {
  const profile = fs.mkdtempSync(path.join(os.tmpdir(), 'shadows-chromium-'));
  const flags = ['--headless', '--disable-gpu', '--enable-unsafe-swiftshader', '--use-angle=swiftshader',
    '--no-sandbox', '--disable-background-networking', '--disable-component-update',
    '--disable-sync', '--no-first-run', '--disable-dev-shm-usage', '--remote-debugging-pipe',
    `--user-data-dir=${profile}`, '--window-size=1280,1024', ...extraFlags, 'about:blank'];
  const proc = spawn(process.env.CHROMIUM || '/usr/bin/chromium', flags,
                     { stdio: ['ignore', 'ignore', 'pipe', 'pipe', 'pipe'], detached: true });
  let stderr = '';
  proc.stderr.on('data', (d) => { stderr += d; });
  const toBrowser = proc.stdio[3], fromBrowser = proc.stdio[4];
  let nextId = 1;
  const pending = new Map(), listeners = [];
  let buffer = Buffer.alloc(0);
  fromBrowser.on('data', (chunk) => {
    buffer = Buffer.concat([buffer, chunk]);
    let end;
    while ((end = buffer.indexOf(0)) >= 0) {
      const message = JSON.parse(buffer.subarray(0, end).toString());
      buffer = buffer.subarray(end + 1);
      if (message.id && pending.has(message.id)) {
        const { resolve, reject } = pending.get(message.id);
        pending.delete(message.id);
        if (message.error) reject(new Error(message.error.message));
        else resolve(message.result);
      } else {
        for (const listener of listeners) listener(message);
      }
    }
  });
  const exited = new Promise((r) => proc.on('exit', r));
  const send = (method, params = {}, sessionId = undefined) => new Promise((resolve, reject) => {
    const id = nextId++;
    pending.set(id, { resolve, reject });
    toBrowser.write(JSON.stringify({ id, method, params, sessionId }) + '\0');
  });
  await Promise.race([send('Browser.getVersion'),
    exited.then(() => { throw new Error('chromium exited: ' + stderr.slice(-2000)); })]);
  return {
    send, listeners,
    async close() {
      try { await Promise.race([send('Browser.close'), new Promise((r) => setTimeout(r, 3000))]); } catch (e) { /* gone */ }
      try { process.kill(-proc.pid); } catch (e) { /* already gone */ }  // its helpers too
      await exited;
      try {
        fs.rmSync(profile, { recursive: true, force: true, maxRetries: 10, retryDelay: 100 });
      } catch (e) { /* a helper still writing: a temporary directory left behind */ }
    },
  };
}

// A tab at `url`: events collected (exceptions, console), evaluate(), waitFor().
// viewport: {width, height} of the page's window (CSS pixels), else the browser's own.
export async function open(browser, url, viewport = null) {
  const { targetId } = await browser.send('Target.createTarget', { url: 'about:blank' });
  const { sessionId } = await browser.send('Target.attachToTarget', { targetId, flatten: true });
  const page = {
    exceptions: [], console: [],
    send: (method, params) => browser.send(method, params, sessionId),
    async evaluate(expression) {
      const r = await page.send('Runtime.evaluate', { expression, returnByValue: true, awaitPromise: true });
      if (r.exceptionDetails) throw new Error(`${expression}: ${r.exceptionDetails.exception?.description ?? r.exceptionDetails.text}`);
      return r.result.value;
    },
    // Polls `expression` until truthy; throws after `ms`.
    async waitFor(expression, ms = 20000) {
      const until = Date.now() + ms;
      for (;;) {
        // Before the page's scripts have run, its names are not there yet: not true yet.
        const value = await page.evaluate(`(() => { try { return ${expression}; } catch (e) { return false; } })()`);
        if (value) return value;
        if (Date.now() > until) throw new Error(`timed out waiting for ${expression}`);
        await new Promise((r) => setTimeout(r, 50));
      }
    },
    close: () => browser.send('Target.closeTarget', { targetId }),
  };
  browser.listeners.push((m) => {
    if (m.sessionId !== sessionId) return;
    if (m.method === 'Runtime.exceptionThrown') {
      const d = m.params.exceptionDetails;
      page.exceptions.push(d.exception?.description ?? d.text);
    } else if (m.method === 'Log.entryAdded') {  // the browser's own lines: WebGL's errors
      page.console.push({ type: m.params.entry.level, text: m.params.entry.text });
    } else if (m.method === 'Runtime.consoleAPICalled') {
      page.console.push({ type: m.params.type, text: m.params.args.map((a) => a.value ?? a.description).join(' ') });
    }
  });
  await page.send('Runtime.enable');
  await page.send('Log.enable');
  await page.send('Page.enable');
  if (viewport) {
    await page.send('Emulation.setDeviceMetricsOverride',
                    { width: viewport.width, height: viewport.height, deviceScaleFactor: 1, mobile: false });
  }
  await page.send('Page.navigate', { url });
  return page;
}

// A PNG (8-bit RGB or RGBA, not interlaced: what the lessons and stb write) as RGBA rows, top
// row first.
export function decodePng(bytes) {
  let pos = 8, width = 0, height = 0, channels = 4;
  const idat = [];
  while (pos < bytes.length) {
    const length = bytes.readUInt32BE(pos), type = bytes.toString('ascii', pos + 4, pos + 8);
    const data = bytes.subarray(pos + 8, pos + 8 + length);
    if (type === 'IHDR') {
      width = data.readUInt32BE(0); height = data.readUInt32BE(4);
      if (data[8] !== 8 || data[12] !== 0 || ![2, 6].includes(data[9])) throw new Error('unsupported PNG');
      channels = data[9] === 6 ? 4 : 3;
    } else if (type === 'IDAT') {
      idat.push(data);
    }
    pos += 12 + length;
  }
  const raw = zlib.inflateSync(Buffer.concat(idat));
  const stride = width * channels, rgba = Buffer.alloc(width * height * 4);
  let prev = Buffer.alloc(stride);
  for (let y = 0; y < height; ++y) {
    const filter = raw[y * (stride + 1)];
    const line = Buffer.from(raw.subarray(y * (stride + 1) + 1, (y + 1) * (stride + 1)));
    for (let i = 0; i < stride; ++i) {
      const a = i >= channels ? line[i - channels] : 0, b = prev[i], c = i >= channels ? prev[i - channels] : 0;
      let p = 0;
      if (filter === 1) p = a;
      else if (filter === 2) p = b;
      else if (filter === 3) p = (a + b) >> 1;
      else if (filter === 4) {
        const pa = Math.abs(b - c), pb = Math.abs(a - c), pc = Math.abs(a + b - 2 * c);
        p = pa <= pb && pa <= pc ? a : pb <= pc ? b : c;
      }
      line[i] = (line[i] + p) & 255;
    }
    for (let x = 0; x < width; ++x) {
      for (let k = 0; k < 4; ++k) rgba[(y * width + x) * 4 + k] = k < channels ? line[x * channels + k] : 255;
    }
    prev = line;
  }
  return { width, height, rgba };
}

// Pixels whose largest colour difference exceeds `levels` (tests/flavour_views.cpp's count).
export function pixelsDiffering(a, b, levels = 0) {
  if (a.width !== b.width || a.height !== b.height) return a.width * a.height + 1;
  let n = 0;
  for (let i = 0; i < a.rgba.length; i += 4) {
    if (Math.abs(a.rgba[i] - b.rgba[i]) > levels || Math.abs(a.rgba[i + 1] - b.rgba[i + 1]) > levels ||
        Math.abs(a.rgba[i + 2] - b.rgba[i + 2]) > levels) ++n;
  }
  return n;
}

// PNG's CRC-32 (zlib.crc32 is newer than Debian's node 18).
const kCrcTable = Array.from({ length: 256 }, (_, n) => {
  let c = n;
  for (let k = 0; k < 8; ++k) c = c & 1 ? 0xedb88320 ^ (c >>> 1) : c >>> 1;
  return c >>> 0;
});
function crc32(bytes) {
  let c = 0xffffffff;
  for (const b of bytes) c = kCrcTable[(c ^ b) & 255] ^ (c >>> 8);
  return (c ^ 0xffffffff) >>> 0;
}

// RGBA rows (top first) as a PNG.
export function encodePng({ width, height, rgba }) {
  const chunk = (type, data) => {
    const head = Buffer.alloc(8);
    head.writeUInt32BE(data.length, 0);
    head.write(type, 4, 'ascii');
    const crc = Buffer.alloc(4);
    crc.writeUInt32BE(crc32(Buffer.concat([head.subarray(4), data])), 0);
    return Buffer.concat([head, data, crc]);
  };
  const ihdr = Buffer.alloc(13);
  ihdr.writeUInt32BE(width, 0); ihdr.writeUInt32BE(height, 4);
  ihdr[8] = 8; ihdr[9] = 6;
  const raw = Buffer.alloc(height * (width * 4 + 1));
  for (let y = 0; y < height; ++y) rgba.copy(raw, y * (width * 4 + 1) + 1, y * width * 4, (y + 1) * width * 4);
  return Buffer.concat([Buffer.from([137, 80, 78, 71, 13, 10, 26, 10]), chunk('IHDR', ihdr),
                        chunk('IDAT', zlib.deflateSync(raw)), chunk('IEND', Buffer.alloc(0))]);
}

// a | b | the pixels that differ (white: by more than 8 levels, grey: by 1 to 8), side by side.
export function sideBySide(a, b) {
  if (a.width !== b.width || a.height !== b.height) return encodePng(a);
  const w = a.width, h = a.height, out = Buffer.alloc(w * 3 * h * 4);
  for (let y = 0; y < h; ++y) {
    for (let x = 0; x < w; ++x) {
      const i = (y * w + x) * 4;
      let d = 0;
      for (let k = 0; k < 3; ++k) d = Math.max(d, Math.abs(a.rgba[i + k] - b.rgba[i + k]));
      const v = d > 8 ? 255 : d > 0 ? 110 : 0;
      a.rgba.copy(out, (y * w * 3 + x) * 4, i, i + 4);
      b.rgba.copy(out, (y * w * 3 + w + x) * 4, i, i + 4);
      out.fill(v, (y * w * 3 + 2 * w + x) * 4, (y * w * 3 + 2 * w + x) * 4 + 3);
      out[(y * w * 3 + 2 * w + x) * 4 + 3] = 255;
    }
  }
  return encodePng({ width: w * 3, height: h, rgba: out });
}

// The mean of each pixel's largest colour difference, in levels.
export function meanDifference(a, b) {
  let sum = 0;
  for (let i = 0; i < a.rgba.length; i += 4) {
    sum += Math.max(Math.abs(a.rgba[i] - b.rgba[i]), Math.abs(a.rgba[i + 1] - b.rgba[i + 1]),
                    Math.abs(a.rgba[i + 2] - b.rgba[i + 2]));
  }
  return sum / (a.rgba.length / 4);
}
