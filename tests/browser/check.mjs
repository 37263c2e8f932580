// Loads every page of the built book in headless Chromium and checks that it
// works offline: no requests leave 127.0.0.1, no console errors, no failed
// same-origin requests, math rendered by KaTeX with its fonts loaded, every
// figure decoded with its smallest text at least 9 px as the page shows it,
// every internal link (and #fragment) resolving, and search returning results. Run through scripts/browser-test, which builds and serves
// the book; by hand:
//
//   node tests/browser/check.mjs --base http://127.0.0.1:8000/ \
//        --summary chapters/SUMMARY.md --screenshot target/browser/screenshot.png
//
// Prints one `FAIL <page>: <what>` line per problem, a summary line
// `browser: N pages, M checks, F failures`, and last `P passed, Q failed`
// (pages; a page outside the sidebar, e.g. print.html reached by a link,
// counts as failed when it has a problem). Exit status 0 only when nothing
// failed. Options: --allow-blocked HOST[,HOST] (requests there are still
// blocked, but only noted), --search-page, --search-word, --screenshot-page,
// --timeout MS; VERBOSE=1 prints each note, TIMING=1 the time per page.

import { chromium } from 'playwright-core';
import { readFileSync, existsSync, mkdirSync, mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';

// ---- options ---------------------------------------------------------------

function parseArgs(argv) {
    const opts = {
        base: null,
        summary: 'chapters/SUMMARY.md',
        screenshot: 'target/browser/screenshot.png',
        screenshotPage: '05_arbitrary_ortho_camera.html',
        screenshotsDir: '',
        searchPage: 'index.html',
        searchWord: 'orthographic',
        chromium: process.env.CHROMIUM || '/usr/bin/chromium',
        timeout: 20000,
        allowBlocked: '',
    };
    for (let i = 2; i < argv.length; i++) {
        const key = argv[i].replace(/^--/, '').replace(/-([a-z])/g, (_, c) => c.toUpperCase());
        if (!(key in opts) || i + 1 >= argv.length) {
            console.error(`check.mjs: unknown or incomplete option ${argv[i]}`);
            process.exit(2);
        }
        opts[key] = argv[++i];
    }
    if (!opts.base) {
        console.error('check.mjs: --base http://127.0.0.1:PORT/ is required');
        process.exit(2);
    }
    if (!opts.base.endsWith('/')) opts.base += '/';
    opts.timeout = Number(opts.timeout);
    opts.allowBlocked = new Set(opts.allowBlocked.split(',').map((h) => h.trim()).filter(Boolean));
    return opts;
}

const opts = parseArgs(process.argv);
const base = new URL(opts.base);
const srcDir = path.dirname(path.resolve(opts.summary));

// ---- the pages: every chapter in SUMMARY.md that has a file ----------------

// Returns [{ page: 'intro.html', source: '/abs/chapters/intro.md' }, ...] in
// sidebar order. Draft chapters (`[Title]()`) have no file and are skipped.
function pagesFromSummary(file) {
    const text = readFileSync(file, 'utf8');
    const pages = [];
    const seen = new Set();
    for (const m of text.matchAll(/\[[^\]]*\]\(([^)]*)\)/g)) {
        const target = m[1].trim().split('#')[0];
        if (target === '' || !target.endsWith('.md')) continue;
        const page = target.replace(/\.md$/, '.html').replace(/(^|\/)README\.html$/, '$1index.html');
        if (seen.has(page)) continue;
        seen.add(page);
        pages.push({ page, source: path.join(srcDir, target) });
    }
    return pages;
}

// Does the markdown contain math? `$` outside code spans/blocks, not escaped.
function sourceHasMath(file) {
    if (!existsSync(file)) return false;
    const md = readFileSync(file, 'utf8')
        .replace(/^(```|~~~)[^\n]*\n[\s\S]*?^\1[^\n]*$/gm, '')
        .replace(/`[^`\n]*`/g, '')
        .replace(/\\\$/g, '');
    return md.includes('$');
}

// ---- figures: the size of their smallest text ------------------------------

// A figure's smallest text, as the page shows it, must be at least MIN_TEXT_PX:
// its size in the figure times the figure's rendered width over its natural
// width. The sizes in the figures' own pixels (tests/lessons/figures.rs checks these
// constants against the code that draws them):
// - diagrams (src/course/diagram/axes.rs): tick values, 0.8 of LABEL_SIZE = 15 px;
// - strips of renders (book/figures/src/lesson09.rs): captions of CAPTION_SIZE;
// - renders: no text at all;
// - SVG charts (src/course/chart.rs): read from the SVG's own font-size attributes.
const MIN_TEXT_PX = 9;
const DIAGRAM_TEXT_PX = 12;
const TEXT_PX = new Map([['09_side_by_side.png', 30]]);
const NO_TEXT = new Set([
    '03_origins.png', '06_ortho_vs_pinhole.png',
    '08_far_fixed_epsilon.png', '08_far_scaled_offset.png', '08_lambert.png',
    '08_shadowless_ortho.png', '08_shadowless_pinhole.png',
    '09_difference.png', '09_mesh.png', '09_shadow_bias.png', '09_shadows.png',
    '09_teapot.png',
    '10_convergence.png', '10_step_cosine.png', '10_step_lens.png', '10_step_mis.png',
    '10_step_nee.png', '10_step_roulette.png', '10_step_specular.png', '10_step_uniform.png',
]);

// The smallest text of the figure `file` (its name) in its own pixels, or null if
// it has none; `svgSizes` are the font sizes an SVG declares.
function smallestText(file, svgSizes) {
    if (file.endsWith('.svg')) return svgSizes.length > 0 ? Math.min(...svgSizes) : null;
    if (NO_TEXT.has(file)) return null;
    return TEXT_PX.get(file) ?? DIAGRAM_TEXT_PX;
}

// ---- results ---------------------------------------------------------------

let checks = 0;
const failures = new Map(); // page -> [what]
const notes = new Map(); // page -> [what], for --allow-blocked hosts: reported, not failed

function check(page, ok, what) {
    checks++;
    if (!ok) fail(page, what);
    return ok;
}

function fail(page, what) {
    if (!failures.has(page)) failures.set(page, []);
    const list = failures.get(page);
    if (!list.includes(what)) {
        list.push(what);
        console.log(`FAIL ${page}: ${what}`);
    }
}

function note(page, what) {
    if (!notes.has(page)) notes.set(page, []);
    const list = notes.get(page);
    if (!list.includes(what)) list.push(what);
}

const hostOf = (u) => {
    try {
        return new URL(u).hostname;
    } catch {
        return '';
    }
};

const isLocal = (u) => {
    try {
        const h = new URL(u).hostname;
        return h === '127.0.0.1' || h === 'localhost' || h === '[::1]';
    } catch {
        return true; // data:, blob:, about: and the like never touch the network
    }
};
const sameOrigin = (u) => {
    try {
        return new URL(u).origin === base.origin;
    } catch {
        return false;
    }
};
const rel = (u) => {
    const url = new URL(u);
    return url.origin === base.origin ? url.pathname.replace(/^\//, '') + url.search + url.hash : u;
};

// ---- browser ---------------------------------------------------------------

const profile = mkdtempSync(path.join(tmpdir(), 'book-browser-'));
const context = await chromium.launchPersistentContext(profile, {
    executablePath: opts.chromium,
    headless: true,
    args: [
        '--headless',
        '--no-sandbox',
        '--disable-gpu',
        '--disable-quic',
        '--no-first-run',
        '--disable-background-networking',
        '--disable-component-update',
        '--disable-sync',
    ],
    viewport: { width: 1280, height: 900 },
    serviceWorkers: 'block',
});
context.setDefaultTimeout(opts.timeout);
context.setDefaultNavigationTimeout(opts.timeout);

// What the checker is doing, for a crash report.
let current = '(startup)';

// Problems are charged to the book page (path, no query or fragment) whose
// document raised them.
const pageName = (u) => {
    try {
        const url = new URL(u);
        return url.origin === base.origin ? url.pathname.replace(/^\//, '') || 'index.html' : current;
    } catch {
        return current;
    }
};
const frameName = (req) => {
    try {
        return pageName(req.frame().url());
    } catch {
        return current; // service worker or detached frame
    }
};

// Pages on which a request to an --allow-blocked host was blocked: the book's
// own script errors that follow from it are notes there, not failures.
const allowedBlocks = new Set();

// The book must work with the network off: block and record anything that
// is not loopback.
await context.route('**/*', (route) => {
    const req = route.request();
    const url = req.url();
    if (isLocal(url)) return route.continue();
    const who = frameName(req);
    if (opts.allowBlocked.has(hostOf(url))) {
        allowedBlocks.add(who);
        note(who, `request to ${url} blocked (allowed by --allow-blocked)`);
    } else {
        fail(who, `request to another host blocked: ${url}`);
    }
    return route.abort('blockedbyclient');
});

// The status of a page's own document is checked by whoever loads it (a page
// check, or the link check for a link target), not by these listeners.
function watch(page) {
    page.on('console', (msg) => {
        if (msg.type() !== 'error') return;
        const who = pageName(page.url());
        const loc = msg.location();
        // Chromium logs every failed load as a console error too; those are
        // reported once already, by the response, requestfailed or route
        // handlers (or, for the document itself, by whoever loaded it).
        if (loc && loc.url && /^Failed to load resource/.test(msg.text())
            && (loc.url === page.url() || sameOrigin(loc.url) || !isLocal(loc.url))) return;
        if (loc && loc.url && opts.allowBlocked.has(hostOf(loc.url))) {
            note(who, `console error: ${msg.text()}`);
            return;
        }
        const where = loc && loc.url ? ` (${rel(loc.url)}${loc.lineNumber ? ':' + loc.lineNumber : ''})` : '';
        fail(who, `console error: ${msg.text()}${where}`);
    });
    page.on('pageerror', (err) => {
        const who = pageName(page.url());
        // mdBook's playground asks play.rust-lang.org for its crate list and
        // does not catch the rejection when that host is unreachable.
        if (allowedBlocks.has(who) && err.message === 'Failed to fetch' && /fetch_with_timeout/.test(err.stack || '')) {
            note(who, `page error: ${err.message} (playground fetch)`);
            return;
        }
        fail(who, `page error: ${err.message}`);
    });
    page.on('requestfailed', (req) => {
        if (req.isNavigationRequest() && req.frame() === page.mainFrame()) return;
        const url = req.url();
        if (!sameOrigin(url)) return; // blocked hosts are already reported
        const error = req.failure()?.errorText || '';
        // A navigation cancels what the previous document was still loading.
        if (error === 'net::ERR_ABORTED') return;
        fail(frameName(req), `request failed: ${rel(url)} (${error})`);
    });
    page.on('response', (res) => {
        const req = res.request();
        if (req.isNavigationRequest() && req.frame() === page.mainFrame()) return;
        if (sameOrigin(res.url()) && res.status() >= 400) {
            fail(frameName(res.request()), `HTTP ${res.status()} for ${rel(res.url())}`);
        }
    });
}

const page = context.pages()[0] || (await context.newPage());
watch(page);

// A second tab to look at link targets that are not among the checked pages.
let probe = null;

// Link targets: path -> { status, ids: Set }
const targets = new Map();

const collectIds = () => {
    const ids = [];
    for (const el of document.querySelectorAll('[id]')) ids.push(el.id);
    for (const el of document.querySelectorAll('a[name]')) ids.push(el.getAttribute('name'));
    return ids;
};

async function target(pathname) {
    if (targets.has(pathname)) return targets.get(pathname);
    if (!probe) {
        probe = await context.newPage();
        watch(probe);
    }
    const saved = current;
    let entry;
    try {
        const res = await probe.goto(new URL(pathname, base).href, { waitUntil: 'load' });
        await probe.waitForLoadState('networkidle').catch(() => {});
        const status = res ? res.status() : 0;
        entry = { status, ids: new Set(status === 200 ? await probe.evaluate(collectIds) : []) };
    } catch (err) {
        entry = { status: 0, ids: new Set(), error: err.message.split('\n')[0] };
    } finally {
        current = saved;
    }
    targets.set(pathname, entry);
    return entry;
}

// ---- checks on one page ----------------------------------------------------

async function checkPage({ page: name, source }) {
    current = name;
    const url = new URL(name, base).href;
    let res;
    try {
        res = await page.goto(url, { waitUntil: 'load' });
    } catch (err) {
        check(name, false, `could not load: ${err.message.split('\n')[0]}`);
        return;
    }
    if (!check(name, res && res.status() === 200, `HTTP ${res ? res.status() : 'no response'} for the page itself`)) return;
    await page.waitForLoadState('networkidle').catch(() => {});

    const info = await page.evaluate(async () => {
        await document.fonts.ready;
        // Images: make lazy ones load, then wait for every one to decode.
        const imgs = [...document.querySelectorAll('img')];
        for (const img of imgs) img.loading = 'eager';
        await Promise.all(imgs.map((img) => img.decode().catch(() => {})));

        // Visible text outside math and code, to look for unrendered TeX.
        const texts = [];
        const walker = document.createTreeWalker(document.body, NodeFilter.SHOW_TEXT, {
            acceptNode(node) {
                const el = node.parentElement;
                if (!el || el.closest('.katex, pre, code, script, style, noscript, template')) return NodeFilter.FILTER_REJECT;
                if (!el.checkVisibility({ visibilityProperty: true })) return NodeFilter.FILTER_REJECT;
                return NodeFilter.FILTER_ACCEPT;
            },
        });
        for (let n = walker.nextNode(); n; n = walker.nextNode()) texts.push(n.data);

        const katexFaces = [...document.fonts]
            .filter((f) => f.family.replace(/["']/g, '').startsWith('KaTeX_'))
            .map((f) => ({ family: f.family.replace(/["']/g, ''), style: f.style, weight: f.weight, status: f.status }));

        const links = [...document.querySelectorAll('a[href]')].map((a) => a.href);
        const sidebar = [...document.querySelectorAll('#mdbook-sidebar ol.chapter a[href]')]
            .map((a) => a.getAttribute('href'))
            .filter((h) => !h.includes('#'));

        return {
            katex: document.querySelectorAll('.katex').length,
            katexErrors: [...document.querySelectorAll('.katex-error')].map((e) => e.getAttribute('title') || e.textContent).slice(0, 5),
            text: texts.join(' ').replace(/\s+/g, ' '),
            innerText: document.body.innerText,
            katexMainLoaded: document.fonts.check('16px KaTeX_Main'),
            katexFaces,
            images: await Promise.all(imgs.map(async (img) => {
                const src = img.currentSrc || img.src;
                // An SVG's font sizes, from its own text (same origin).
                let svgSizes = [];
                if (/\.svg($|[?#])/.test(src)) {
                    const text = await fetch(src).then((r) => r.text()).catch(() => '');
                    svgSizes = [...text.matchAll(/font-size="([0-9.]+)(px)?"/g)].map((m) => Number(m[1]));
                }
                return {
                    src,
                    complete: img.complete,
                    w: img.naturalWidth,
                    shown: img.getBoundingClientRect().width,
                    svgSizes,
                };
            })),
            links,
            sidebar,
            ids: [
                ...[...document.querySelectorAll('[id]')].map((el) => el.id),
                ...[...document.querySelectorAll('a[name]')].map((el) => el.getAttribute('name')),
            ],
        };
    });
    targets.set(new URL(url).pathname, { status: 200, ids: new Set(info.ids) });

    // Math.
    if (sourceHasMath(source)) {
        check(name, info.katex > 0, 'the source has $ math but the page has no .katex elements');
        check(name, info.katexErrors.length === 0, `KaTeX errors: ${info.katexErrors.join(' | ')}`);
        const raw = [];
        for (const [label, re] of [
            ['$$', /\$\$/],
            ['\\frac', /\\frac/],
            ['\\mathbf', /\\mathbf/],
            ['$...\\command', /\$[^$\n]{0,80}\\[A-Za-z]+/],
        ]) {
            const m = re.exec(info.text);
            if (m) raw.push(`${label} in "${info.text.slice(Math.max(0, m.index - 30), m.index + 40).trim()}"`);
        }
        check(name, raw.length === 0, `raw TeX in the visible text: ${raw.join('; ')}`);
        // The same on document.body.innerText as a whole (KaTeX's MathML copy
        // of the TeX source is not part of it).
        const m = /\$\$|\\frac|\\mathbf/.exec(info.innerText);
        check(name, !m, `raw TeX in document.body.innerText: "${m ? info.innerText.slice(Math.max(0, m.index - 30), m.index + 40).replace(/\s+/g, ' ').trim() : ''}"`);
        const main = info.katexFaces.filter((f) => f.family === 'KaTeX_Main');
        check(name, info.katexMainLoaded && main.some((f) => f.status === 'loaded'),
            `KaTeX_Main font not loaded (faces: ${main.map((f) => `${f.weight}/${f.style}:${f.status}`).join(', ') || 'none declared'})`);
        const broken = info.katexFaces.filter((f) => f.status === 'error');
        check(name, broken.length === 0, `KaTeX fonts failed to load: ${broken.map((f) => `${f.family} ${f.weight} ${f.style}`).join(', ')}`);
    }

    // Figures: loaded, and their smallest text legible as the page shows it.
    for (const img of info.images) {
        if (!check(name, img.complete && img.w > 0, `image did not load: ${rel(img.src)}`)) continue;
        const file = decodeURIComponent(new URL(img.src).pathname.split('/').pop());
        const text = smallestText(file, img.svgSizes);
        if (text === null || img.shown === 0) continue;
        const shown = (text * img.shown) / img.w;
        check(name, shown >= MIN_TEXT_PX,
            `figure ${file}: its ${text.toFixed(1)} px text is shown at ${shown.toFixed(1)} px ` +
            `(${Math.round(img.shown)} of ${img.w} px wide), less than ${MIN_TEXT_PX} px`);
    }

    // Sidebar: the chapters it shows are the ones SUMMARY.md lists.
    if (name === pages[0].page) {
        const want = pages.map((p) => p.page).join(' ');
        const got = info.sidebar.map((h) => new URL(h, url).pathname.replace(/^\//, '')).join(' ');
        check(name, got === want, `sidebar shows [${got}], SUMMARY.md lists [${want}]`);
    }

    // Internal links: checked once every page has been visited, so that the
    // checked pages need not be loaded twice.
    links.set(name, [...new Set(info.links.filter(sameOrigin))]);
}

const links = new Map(); // page -> [absolute same-origin href]

async function checkLinks() {
    for (const [name, hrefs] of links) {
        for (const href of hrefs) {
            const u = new URL(href);
            const t = await target(u.pathname);
            current = name;
            if (!check(name, t.status === 200, `broken link ${rel(href)}: ${t.error || 'HTTP ' + t.status}`)) continue;
            let frag = u.hash.replace(/^#/, '');
            try {
                frag = decodeURIComponent(frag);
            } catch {
                // keep it as written
            }
            if (frag !== '') check(name, t.ids.has(frag), `broken link ${rel(href)}: no element with id "${frag}"`);
        }
    }
}

async function checkSearch(name, word) {
    current = name;
    await page.goto(new URL(name, base).href, { waitUntil: 'load' });
    await page.waitForLoadState('networkidle').catch(() => {});
    try {
        await page.locator('#mdbook-search-toggle').waitFor({ state: 'visible' });
        await page.locator('body').press('s');
        const bar = page.locator('#mdbook-searchbar');
        await bar.waitFor({ state: 'visible' });
        // The index is loaded on first open; the bar is "searching" until then.
        await page.locator('#mdbook-searchbar-outer:not(.searching)').waitFor({ state: 'attached' });
        await bar.click();
        await bar.pressSequentially(word, { delay: 20 });
        const first = page.locator('#mdbook-searchresults > li').first();
        await first.waitFor({ state: 'visible', timeout: 5000 });
        const n = await page.locator('#mdbook-searchresults > li').count();
        const header = (await page.locator('#mdbook-searchresults-header').innerText()).trim();
        const href = await first.locator('a').first().getAttribute('href');
        check(name, n > 0, `search for "${word}" shows no results`);
        console.log(`search "${word}" on ${name}: ${n} results ("${header}")`);
        if (href) {
            const t = await target(new URL(href, page.url()).pathname);
            current = name;
            check(name, t.status === 200, `first search result links to ${href}: HTTP ${t.status}`);
        }
    } catch (err) {
        check(name, false, `search for "${word}" failed: ${err.message.split('\n')[0]}`);
    }
}

// ---- run -------------------------------------------------------------------

const started = Date.now();
const pages = pagesFromSummary(opts.summary);
if (pages.length === 0) {
    console.error(`check.mjs: no chapters found in ${opts.summary}`);
    process.exit(2);
}
let exitCode = 0;
try {
    for (const p of pages) {
        const t = Date.now();
        await checkPage(p);
        if (process.env.TIMING) console.log(`time ${p.page} ${Date.now() - t}ms`);
    }
    await checkLinks();

    const searchOn = pages.some((p) => p.page === opts.searchPage) ? opts.searchPage : pages[0].page;
    await checkSearch(searchOn, opts.searchWord);

    if (opts.screenshotsDir) {
        // One full-page screenshot per page, to look at every page before a release.
        mkdirSync(path.resolve(opts.screenshotsDir), { recursive: true });
        for (const p of pages) {
            current = p.page;
            await page.goto(new URL(p.page, base).href, { waitUntil: 'load' });
            await page.waitForLoadState('networkidle').catch(() => {});
            await page.evaluate(() => document.fonts.ready);
            const file = path.join(path.resolve(opts.screenshotsDir), p.page.replace(/\.html$/, '.png'));
            await page.screenshot({ path: file, fullPage: true });
        }
        console.log(`screenshots of ${pages.length} pages: ${path.resolve(opts.screenshotsDir)}`);
    }

    if (opts.screenshot) {
        const shotPage = pages.some((p) => p.page === opts.screenshotPage) ? opts.screenshotPage : pages[0].page;
        current = shotPage;
        await page.goto(new URL(shotPage, base).href, { waitUntil: 'load' });
        await page.waitForLoadState('networkidle').catch(() => {});
        await page.evaluate(() => document.fonts.ready);
        mkdirSync(path.dirname(path.resolve(opts.screenshot)), { recursive: true });
        await page.screenshot({ path: opts.screenshot, fullPage: true });
        console.log(`screenshot of ${shotPage}: ${path.resolve(opts.screenshot)}`);
    }
} catch (err) {
    fail(current, `checker crashed: ${err.stack || err}`);
} finally {
    await context.close().catch(() => {});
    rmSync(profile, { recursive: true, force: true });
}

const failedPages = pages.filter((p) => failures.has(p.page)).length;
const stray = [...failures.keys()].filter((k) => !pages.some((p) => p.page === k));
const nFailures = [...failures.values()].reduce((a, l) => a + l.length, 0);
if (notes.size > 0) {
    const hosts = [...opts.allowBlocked].join(', ');
    console.log(`note: ${notes.size} page(s) asked ${hosts} (blocked; tolerated by --allow-blocked): ${[...notes.keys()].join(' ')}`);
    if (process.env.VERBOSE) for (const [who, list] of notes) for (const what of list) console.log(`note ${who}: ${what}`);
}
for (const p of pages) if (!failures.has(p.page)) console.log(`ok   ${p.page}`);
console.log(`browser: ${pages.length} pages, ${checks} checks, ${nFailures} failures (${((Date.now() - started) / 1000).toFixed(1)}s)`);
console.log(`${pages.length - failedPages} passed, ${failedPages + stray.length} failed`);
if (nFailures > 0) exitCode = 1;
process.exit(exitCode);
