// The page in a real browser (issue 41): Debian's Chromium, headless, driven by puppeteer-core
// (never a downloaded browser). Serves build/wasm/site with a tiny static server, then:
//  - every shipped sample: its errors are the CLI's (klueng-cli check); a runnable one is run
//    with Go to its end, and the page's cycle time and finished part equal
//    `klueng-cli simulate --cycle-time --features` (0.1 s, 0.01 mm);
//  - sample 01 has no diagnostics; an error typed on line 9 is marked on line 9, in English
//    and in Thai;
//  - the first load is under 5 MB gzipped; the worker checks a 5,000-line program in under 200 ms;
//  - with --screenshots DIR: the page at 1366×768 and 800×400 in English and Thai.
// Usage: node web/tests/browser_test.mjs [--screenshots DIR]
// Environment: KLUENG_SITE (build/wasm/site), KLUENG_CLI (build/default/src/cli/klueng-cli),
// CHROMIUM (/usr/bin/chromium).
import { execFileSync, spawnSync } from 'node:child_process';
import fs from 'node:fs';
import http from 'node:http';
import path from 'node:path';
import zlib from 'node:zlib';
import { fileURLToPath } from 'node:url';
import puppeteer from 'puppeteer-core';

const root = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../..');
const site = process.env.KLUENG_SITE || path.join(root, 'build/wasm/site');
const cli = process.env.KLUENG_CLI || path.join(root, 'build/default/src/cli/klueng-cli');
const chromium = process.env.CHROMIUM || '/usr/bin/chromium';
const samplesDir = path.join(root, 'resources/samples');
const shotsAt = process.argv.indexOf('--screenshots');
const shotsDir = shotsAt > 0 ? path.resolve(process.argv[shotsAt + 1]) : '';

let failures = 0;
function check(ok, what) {
  console.log(`${ok ? 'ok  ' : 'FAIL'} ${what}`);
  if (!ok) failures += 1;
}

// ---------------------------------------------------------------- a static server

const types = { '.html': 'text/html; charset=utf-8', '.js': 'text/javascript', '.css': 'text/css',
  '.wasm': 'application/wasm', '.png': 'image/png' };
const server = http.createServer((req, res) => {
  const name = decodeURIComponent(new URL(req.url, 'http://x').pathname);
  const file = path.join(site, name === '/' ? 'index.html' : name);
  if (!file.startsWith(site) || !fs.existsSync(file) || !fs.statSync(file).isFile()) {
    res.writeHead(404).end();
    return;
  }
  res.writeHead(200, { 'Content-Type': types[path.extname(file)] || 'application/octet-stream' });
  fs.createReadStream(file).pipe(res);
});
await new Promise((resolve) => server.listen(0, '127.0.0.1', resolve));
const base = `http://127.0.0.1:${server.address().port}/`;

// Chromium's profile and temporary files stay in the build folder, removed at the end.
const scratch = fs.mkdtempSync(path.join(path.dirname(site), 'browser-'));
const browser = await puppeteer.launch({
  executablePath: chromium,
  headless: true,
  userDataDir: path.join(scratch, 'profile'),
  env: { ...process.env, TMPDIR: scratch, HOME: scratch },
  args: ['--no-sandbox', '--disable-gpu', '--no-first-run', '--disable-dev-shm-usage'],
});

try {
  const page = await browser.newPage();
  page.on('pageerror', (e) => check(false, `no error in the page: ${e.message}`));
  page.on('console', (m) => { if (m.type() === 'error') console.log(`  console: ${m.text()}`); });
  await page.setViewport({ width: 1366, height: 768 });

  async function open(sample, lang = 'en') {
    await page.goto(`${base}?sample=${encodeURIComponent(sample)}`);
    await page.evaluate((l) => localStorage.setItem('klueng.lang', l), lang);
    await page.goto(`${base}?sample=${encodeURIComponent(sample)}`);
    await page.waitForSelector('body[data-ready="yes"][data-checked="yes"]', { timeout: 60000 });
  }
  const diagnosticsShown = () => page.$$eval('#diagnostics li[data-code]', (lis) => lis.map((li) => ({
    line: Number(li.dataset.line), code: li.dataset.code, severity: li.dataset.severity, text: li.textContent })));

  async function runToEnd() {
    await page.select('#speed', '0');
    await page.click('#go');
    await page.waitForFunction(
      () => ['finished', 'alarm'].includes(document.body.dataset.run) && document.body.dataset.part === 'yes'
        || document.querySelector('#message').textContent !== '' && document.body.dataset.run === 'ready',
      { timeout: 120000 });
    return page.evaluate(() => ({
      state: document.body.dataset.run,
      cycle: document.querySelector('#st-cycle').textContent,
      features: [...document.querySelectorAll('#features li[data-kind]')].map((li) => li.textContent),
      message: document.querySelector('#message').textContent,
    }));
  }

  // ------------------------------------------------------------ every sample against the CLI
  const numbers = (s) => (s.match(/-?\d+(?:\.\d+)?/g) || []).map(Number);
  const samples = fs.readdirSync(samplesDir).filter((f) => /\.(txt|nc)$/.test(f)).sort();
  for (const sample of samples) {
    const file = path.join(samplesDir, sample);
    await open(sample);
    const shown = await diagnosticsShown();
    const cliCheck = JSON.parse(spawnSync(cli, ['check', file, '--json', '--lang', 'en'], { encoding: 'utf8' }).stdout);
    const errorsOf = (list) => list.filter((d) => d.severity === 'error').map((d) => `${d.line}:${d.code}`).sort();
    check(JSON.stringify(errorsOf(shown)) === JSON.stringify(errorsOf(cliCheck)),
      `${sample}: the page's errors are the CLI's (${errorsOf(cliCheck).join(' ') || 'none'})`);
    if (sample.startsWith('01-')) check(shown.length === 0, `${sample}: no diagnostics`);
    const sim = spawnSync(cli, ['simulate', file, '--cycle-time', '--features', '--no-persist', '--lang', 'en'],
      { encoding: 'utf8', env: { ...process.env, HOME: scratch, XDG_DATA_HOME: scratch } });
    const lines = sim.stdout.trim().split('\n').filter(Boolean);
    const got = await runToEnd();
    if (errorsOf(cliCheck).length) {
      check(got.state === 'ready' && got.features.length === 0, `${sample}: has errors, so Go does not run it`);
      continue;
    }
    const cliCycle = Number(lines[lines.length - 1]);
    const cliFeatures = lines.slice(0, -1);
    const pageCycle = numbers(got.cycle)[0];
    check(Math.abs(pageCycle - cliCycle) <= 0.1, `${sample}: cycle time ${got.cycle} = CLI ${cliCycle} s (0.1 s)`);
    let same = got.features.length === cliFeatures.length;
    for (let i = 0; same && i < cliFeatures.length; ++i) {
      const a = numbers(got.features[i]);
      const b = numbers(cliFeatures[i]);
      same = a.length === b.length && a.every((v, k) => Math.abs(v - b[k]) <= 0.01);
      if (!same) console.log(`  page: ${got.features[i]}\n  cli:  ${cliFeatures[i]}`);
    }
    check(same, `${sample}: ${got.features.length} finished features (${got.features.filter((f) => f.includes('Ø')).length} with Ø) = CLI's to 0.01 mm`);
    if (sim.status !== 0) check(got.state === 'alarm', `${sample}: the CLI's alarm stops the page's run too`);
  }

  // ------------------------------------------------------------ the real-style programs, core to core
  // tests/real-style/programs (shop programs' forms): the module in the page's worker checks and
  // runs each as klueng-cli does: the same errors, cycle time and finished part.
  {
    const dir = path.join(root, 'tests/real-style/programs');
    const programs = fs.existsSync(dir) ? fs.readdirSync(dir).filter((f) => /\.(nc|txt|tap)$/i.test(f)).sort() : [];
    await page.evaluate(() => {
      window.testWorker = new Worker('worker.js');
      let id = 0;
      window.ask = (msg) => new Promise((resolve) => {
        const mine = ++id;
        window.testWorker.onmessage = (e) => { if (e.data.id === mine) resolve(e.data.result || { error: e.data.error }); };
        window.testWorker.postMessage({ ...msg, id: mine });
      });
    });
    let agree = 0;
    for (const name of programs) {
      const file = path.join(dir, name);
      const bytes = [...fs.readFileSync(file)];
      const page1 = await page.evaluate(async (b) => {
        const program = (() => {
          const u = new Uint8Array(b);
          try { return new TextDecoder('utf-8', { fatal: true }).decode(u); } catch { return new TextDecoder('windows-874').decode(u); }
        })().replace(/\r\n?/g, '\n');
        const c = await window.ask({ type: 'check', text: program, machine: '', units: 0, lang: 0 });
        const r = await window.ask({ type: 'run', text: program, machine: '', units: 0, lang: 0 });
        return { errors: c.diagnostics.filter((d) => d.severity === 'error').map((d) => `${d.line}:${d.code}`),
          ok: r.ok, cycle: r.cycleTime, features: (r.features || []).map((f) => f.text) };
      }, bytes);
      const cliCheck = JSON.parse(spawnSync(cli, ['check', file, '--json', '--lang', 'en'], { encoding: 'utf8' }).stdout);
      const cliErrors = cliCheck.filter((d) => d.severity === 'error' && path.basename(d.file) === name)
        .map((d) => `${d.line}:${d.code}`);
      const sim = spawnSync(cli, ['simulate', file, '--cycle-time', '--features', '--no-persist', '--lang', 'en'],
        { encoding: 'utf8', env: { ...process.env, HOME: scratch, XDG_DATA_HOME: scratch } });
      const lines = sim.stdout.trim().split('\n').filter(Boolean);
      let same = JSON.stringify(page1.errors.sort()) === JSON.stringify(cliErrors.sort());
      if (same && page1.ok && lines.length) {
        const cliCycle = Number(lines[lines.length - 1]);
        same = Math.abs(page1.cycle - cliCycle) <= 0.1 && page1.features.length === lines.length - 1 &&
          page1.features.every((f, i) => {
            const a = numbers(f);
            const b = numbers(lines[i]);
            return a.length === b.length && a.every((v, k) => Math.abs(v - b[k]) <= 0.01);
          });
      } else if (same) {
        same = !page1.ok === (lines.length === 0);
      }
      if (!same) console.log(`  ${name}: page ${JSON.stringify(page1).slice(0, 300)}\n    cli errors ${cliErrors} stdout ${lines.slice(-2)}`);
      agree += same ? 1 : 0;
    }
    await page.evaluate(() => window.testWorker.terminate());
    check(programs.length > 0 && agree === programs.length,
      `real-style programs: ${agree}/${programs.length} checked and run by the page's module as by klueng-cli`);
  }

  // ------------------------------------------------------------ an error typed, in both languages
  for (const lang of ['en', 'th']) {
    await open('01-step-shaft.txt', lang);
    await page.click('.cm-content');
    await page.keyboard.down('Control');
    await page.keyboard.press('Home');
    await page.keyboard.up('Control');
    for (let i = 1; i < 9; ++i) await page.keyboard.press('ArrowDown');
    await page.keyboard.press('End');
    await page.keyboard.type(' G999');
    await page.waitForFunction(() => document.querySelector('#diagnostics li[data-code="E114"]'), { timeout: 20000 });
    const shown = await diagnosticsShown();
    const e114 = shown.find((d) => d.code === 'E114');
    check(e114 && e114.line === 9 && e114.severity === 'error', `${lang}: the typed G999 is E114 on line 9`);
    const thai = /[\u0E00-\u0E7F]/.test(e114 ? e114.text : '');
    check(lang === 'th' ? thai : !thai && /not a G code/.test(e114.text), `${lang}: its message is in ${lang === 'th' ? 'Thai' : 'English'}: ${e114 && e114.text}`);
    // The mark: an error underline on line 9 and the gutter's error marker beside it.
    const marked = await page.evaluate(() => {
      const lines = [...document.querySelectorAll('.cm-content .cm-line')];
      const line = lines.findIndex((l) => l.querySelector('.cm-lintRange-error')) + 1;
      const marker = document.querySelector('.cm-gutter-lint .cm-lint-marker-error');
      const row = lines[8] && lines[8].getBoundingClientRect();
      const m = marker && marker.getBoundingClientRect();
      return { line, gutter: !!(m && row && Math.abs(m.top + m.height / 2 - (row.top + row.height / 2)) < row.height) };
    });
    check(marked.line === 9 && marked.gutter, `${lang}: line 9 is marked in the text and the gutter`);
  }

  // ------------------------------------------------------------ opened from a file (file://)
  {
    const url = `file://${path.join(site, 'index.html')}?sample=01-step-shaft.txt`;
    await page.goto(url);
    await page.evaluate(() => localStorage.setItem('klueng.lang', 'en'));
    await page.goto(url);
    await page.waitForSelector('body[data-ready="yes"][data-checked="yes"]', { timeout: 60000 });
    const shown = await diagnosticsShown();
    const got = await runToEnd();
    check(shown.length === 0 && got.state === 'finished' && got.features.length > 0 && /77\.8/.test(got.cycle),
      `from file://: sample 01 is checked and runs to its end (${got.cycle}, ${got.features.length} features)`);
  }

  // ------------------------------------------------------------ the check of 5,000 lines
  await open('01-step-shaft.txt');
  const big = ['O0005', 'G21 G40 G97 G99', 'T0101', 'G50 S2500', 'G96 S180 M03', 'G00 X52. Z2. M08'];
  for (let i = 0; big.length < 4997; ++i) {
    const d = (50 - (i % 40) * 0.5).toFixed(1);
    big.push(i % 2 ? 'G00 X52. Z2.' : `N${(i % 9000) + 100} G01 X${d} Z${(-(i % 80) - 1).toFixed(1)} F0.2`);
  }
  big.push('G00 X100. Z100. M09', 'M05', 'M30');
  const timing = await page.evaluate(async (program) => {
    // The page's own worker, asked as the editor asks it; the time measured inside the worker.
    const w = new Worker('worker.js');
    const ask = (msg) => new Promise((resolve) => { w.onmessage = (e) => resolve(e.data.result); w.postMessage(msg); });
    await ask({ id: 1, type: 'info', lang: 0 });
    const times = [];
    let diagnostics = 0;
    for (let k = 0; k < 5; ++k) {
      const t0 = performance.now();
      const r = await ask({ id: 2 + k, type: 'check', text: program, machine: '', units: 0, lang: 0 });
      times.push({ worker: r.ms, roundTrip: performance.now() - t0 });
      diagnostics = r.diagnostics.length;
    }
    w.terminate();
    return { times, diagnostics };
  }, big.join('\n'));
  const best = Math.min(...timing.times.map((x) => x.worker));
  const median = timing.times.map((x) => x.worker).sort((a, b) => a - b)[2];
  console.log(`  5,000-line check in the worker: ${timing.times.map((x) => `${x.worker.toFixed(0)}/${x.roundTrip.toFixed(0)}`).join(', ')} ms (worker/round trip), ${timing.diagnostics} diagnostics`);
  check(big.length === 5000 && median < 200, `the worker checks ${big.length} lines in ${median.toFixed(0)} ms (median of 5; best ${best.toFixed(0)}) < 200 ms`);

  // ------------------------------------------------------------ the first load's size
  // What a browser fetches from a server: the page, its scripts, the module (klueng-single.js
  // is fetched only by a page opened from a file).
  let gz = 0;
  let raw = 0;
  for (const f of ['index.html', 'style.css', 'app.js', 'worker.js', 'klueng.js', 'klueng.wasm']) {
    const bytes = fs.readFileSync(path.join(site, f));
    raw += bytes.length;
    gz += zlib.gzipSync(bytes, { level: 9 }).length;
    console.log(`  ${f}: ${bytes.length} bytes, ${zlib.gzipSync(bytes, { level: 9 }).length} gzipped`);
  }
  const single = fs.readFileSync(path.join(site, 'klueng-single.js'));
  console.log(`  first load: ${(raw / 1e6).toFixed(2)} MB, ${(gz / 1e6).toFixed(2)} MB gzipped` +
    ` (from a file: klueng-single.js ${(single.length / 1e6).toFixed(2)} MB instead of klueng.js + .wasm)`);
  check(gz < 5e6, `the first load is ${(gz / 1e6).toFixed(2)} MB gzipped (< 5 MB)`);

  // ------------------------------------------------------------ screenshots to look at
  if (shotsDir) {
    fs.mkdirSync(shotsDir, { recursive: true });
    for (const [w, h] of [[1366, 768], [800, 400]]) {
      for (const lang of ['en', 'th']) {
        await page.setViewport({ width: w, height: h });
        await open('01-step-shaft.txt', lang);
        await page.select('#speed', '0');
        await page.click('#go');
        await page.waitForSelector('body[data-part="yes"]', { timeout: 60000 });
        // The cursor on a block, for its explain line.
        await page.focus('.cm-content');
        await page.keyboard.down('Control');
        await page.keyboard.press('Home');
        await page.keyboard.up('Control');
        for (let i = 0; i < 14; ++i) await page.keyboard.press('ArrowDown');
        await new Promise((r) => setTimeout(r, 400));
        const file = path.join(shotsDir, `page-${w}x${h}-${lang}.png`);
        await page.screenshot({ path: file });
        console.log(`  screenshot ${file}`);
        // And the tool in the cut: Stop, then Step to the middle of the roughing.
        await page.click('#stop');
        for (let i = 0; i < 10; ++i) {
          await page.click('#step');
          await page.waitForFunction(() => document.body.dataset.run === 'paused', { timeout: 30000 });
        }
        const cutting = path.join(shotsDir, `page-${w}x${h}-${lang}-cutting.png`);
        await page.screenshot({ path: cutting });
        console.log(`  screenshot ${cutting}`);
      }
    }
  }
} finally {
  await browser.close();
  server.close();
  fs.rmSync(scratch, { recursive: true, force: true });
}

console.log(failures ? `${failures} FAILED` : 'all passed');
process.exit(failures ? 1 : 0);
