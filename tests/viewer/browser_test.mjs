// The viewer in a real browser (docs/spec.md §3.12): for each spec, `relpos view` writes the
// page, headless Chromium (Debian's, driven by playwright-core) opens it from disk, and
//  - the scene is drawn (a screenshot, and a share of the canvas's pixels not background);
//  - each branch's copy of the mobile object starts at the branch's nearest pose;
//  - dragging a slider with the mouse (and Home/End on the keyboard) moves the object, and the
//    picture with it;
//  - with --collision, the nearest collision-free pose is shown where the result has one;
//  - every pose the page shows satisfies the spec, judged by the tests' evaluator (pose_check,
//    written from docs/spec.md alone), not by the page or by relpos.
// usage: node browser_test.mjs OUT_DIR SPEC[::collision]...
// env: RELPOS_CLI, RELPOS_POSE_CHECK, RELPOS_PLAYWRIGHT (its node_modules folder), CHROMIUM.
import { execFileSync } from 'node:child_process';
import { existsSync, mkdirSync } from 'node:fs';
import { createRequire } from 'node:module';
import { basename, join, resolve } from 'node:path';
import { pathToFileURL } from 'node:url';

const [outDir, ...specs] = process.argv.slice(2);
const cli = process.env.RELPOS_CLI, poseCheck = process.env.RELPOS_POSE_CHECK;
const chromiumPath = process.env.CHROMIUM || '/usr/bin/chromium';
let failures = 0;
function check(ok, what) {
  if (!ok) {
    ++failures;
    console.error('FAIL: ' + what);
  }
}
if (!existsSync(chromiumPath)) {
  console.error(`FAIL: no Chromium at ${chromiumPath}: install Debian's chromium (scripts/install_deps.sh --tests)`);
  process.exit(1);
}
const { chromium } = createRequire(resolve(process.env.RELPOS_PLAYWRIGHT, 'noop.js'))('playwright-core');
mkdirSync(outDir, { recursive: true });

// The flags a root, offline, GPU-less machine needs; WebGL from SwiftShader.
const browser = await chromium.launch({
  executablePath: chromiumPath,
  args: ['--no-sandbox', '--disable-gpu', '--use-angle=swiftshader', '--enable-unsafe-swiftshader',
    '--disable-background-networking', '--disable-component-update', '--disable-sync', '--no-first-run'],
});

function distance(a, b) {
  let d = 0;
  for (let i = 0; i < 16; ++i) d = Math.max(d, Math.abs(a[i] - b[i]));
  return d;
}

// Column-major (three.js) to the row-major line pose_check reads.
function rowMajor(m) {
  const out = [];
  for (let r = 0; r < 4; ++r) for (let c = 0; c < 4; ++c) out.push(m[c * 4 + r]);
  return out.join(' ');
}

async function viewSpec(entry) {
  const [spec, option] = entry.split('::');
  const name = basename(spec, '.json');
  const page_file = resolve(outDir, name + '.html');
  const args = ['view', spec, '-o', page_file, '--samples', '4'];
  if (option === 'collision') args.push('--collision');
  execFileSync(cli, args, { stdio: ['ignore', 'ignore', 'inherit'] });
  const page = await browser.newPage({ viewport: { width: 1100, height: 720 } });
  const errors = [];
  page.on('pageerror', (e) => errors.push(String(e)));
  await page.goto(pathToFileURL(page_file).href);
  await page.waitForFunction(() => window.relposViewer !== undefined, null, { timeout: 30000 });
  check(await page.evaluate(() => window.relposViewer.ready), `${name}: the page is not ready (${await page.evaluate(() => window.relposViewer.error)})`);
  const viewer = () => page.evaluate(() => window.relposViewer);
  await page.screenshot({ path: resolve(outDir, name + '.png') });
  const stats = await page.evaluate(() => window.relposViewer.stats());
  check(stats.drawn > 0.002 * stats.width * stats.height, `${name}: only ${stats.drawn} of ${stats.width}x${stats.height} pixels drawn`);
  const scene = await page.evaluate(() => window.relposViewer.scene);
  const size = scene.size;
  const poses = [];
  const branches = Math.min(scene.branches.length, 4);
  check(scene.branches.length === 0 || (await page.evaluate(() => window.relposViewer.branch())) >= 0, `${name}: no branch chosen`);
  for (let i = 0; i < branches; ++i) {
    const b = scene.branches[i];
    await page.click(`#branch-${i}`);
    check((await page.evaluate(() => window.relposViewer.branch())) === i, `${name}: clicking branch ${i} did not choose it`);
    // With collision filtering: the nearest collision-free pose as a ghost where there is one.
    if (b.collision) {
      const free = await page.evaluate(() => window.relposViewer.freeMatrix());
      const expected = b.collision.nearest_free;
      check(expected === null ? free === null : free !== null && distance(free, expected) <= 1e-12 * Math.max(1, size), `${name} #${i}: the collision-free ghost is not at the nearest free pose`);
    }
    const start = await page.evaluate(() => window.relposViewer.mobileMatrix());
    check(start && distance(start, b.nearest.pose) <= 1e-9 * Math.max(1, size), `${name} #${i}: the object is not at the nearest pose`);
    if (start) poses.push(start);
    for (let k = 0; k < b.parameters.length; ++k) {
      const slider = page.locator(`#param-${k}`);
      const box = await slider.boundingBox();
      const moving = b.parameters[k].motion.type !== 'none' && b.model.range[k][1] > b.model.range[k][0];
      let before = await page.evaluate(() => window.relposViewer.mobileMatrix());
      let pixels = (await page.evaluate(() => window.relposViewer.stats())).checksum;
      // A user's drag: the mouse down at one point of the track and up at another.
      for (const [from, to] of [[0.5, 0.12], [0.12, 0.88]]) {
        await page.mouse.move(box.x + box.width * from, box.y + box.height / 2);
        await page.mouse.down();
        await page.mouse.move(box.x + box.width * to, box.y + box.height / 2, { steps: 4 });
        await page.mouse.up();
        const after = await page.evaluate(() => window.relposViewer.mobileMatrix());
        const now = (await page.evaluate(() => window.relposViewer.stats())).checksum;
        if (after) poses.push(after);
        if (moving && after && before) {
          check(distance(after, before) > 1e-6 * Math.max(1, size), `${name} #${i}: dragging ${b.parameters[k].name} did not move the object`);
          check(now !== pixels, `${name} #${i}: dragging ${b.parameters[k].name} did not change the picture`);
        }
        before = after;
        pixels = now;
      }
      for (const key of ['End', 'Home']) {
        await slider.focus();
        await page.keyboard.press(key);
        const value = (await page.evaluate(() => window.relposViewer.theta()))[k];
        const expected = b.model.range[k][key === 'End' ? 1 : 0];
        check(Math.abs(value - expected) <= 1e-9 * Math.max(1, Math.abs(expected)), `${name} #${i}: ${key} put ${b.parameters[k].name} at ${value}, not ${expected}`);
        const m = await page.evaluate(() => window.relposViewer.mobileMatrix());
        if (m) poses.push(m);
      }
    }
    await page.click('#reset');
    const back = await page.evaluate(() => window.relposViewer.mobileMatrix());
    check(back && distance(back, b.nearest.pose) <= 1e-9 * Math.max(1, size), `${name} #${i}: 'nearest pose' did not bring the object back`);
  }
  check(errors.length === 0, `${name}: the page threw: ${errors.join('; ')}`);
  await page.close();
  console.log(`${name}: ${scene.branches.length} branches, ${poses.length} poses shown, ${stats.drawn} pixels drawn`);
  if (poses.length === 0) return;
  // Every pose shown, judged by the evaluator.
  const out = execFileSync(poseCheck, [spec], { input: poses.map(rowMajor).join('\n') + '\n' }).toString().trim().split('\n');
  out.forEach((line, j) => {
    const [v, which] = line.split(' ').map(Number);
    check(v <= 1e-7 * Math.max(1, size), `${name}: a pose the page showed breaks constraint ${which} by ${v}`);
  });
}

try {
  for (const s of specs) await viewSpec(s);
} finally {
  await browser.close();
}
if (failures > 0) {
  console.error(`${failures} failures`);
  process.exit(1);
}
