// Render times of the dashboard in Debian's chromium (headless, playwright-core), measured in
// the page with performance marks: the job page of a long job (time to the first plot, time
// until the residual plot holds every iteration) and the job list with many jobs. Prints one
// JSON object. Driven by bench_dashboard.py, which starts kontaktd and fills it.
import { createRequire } from "node:module";
import { dirname, join } from "node:path";

const env = process.env;
const { chromium } = createRequire(join(dirname(env.NODE_MODULES), "index.js"))("playwright-core");
const URL = env.KONTAKTD_URL, JOB = env.JOB_ID, N = Number(env.ITERATIONS), RUNS = Number(env.RUNS);
const LIST_LABEL = env.LIST_LABEL, N_JOBS = Number(env.LIST_JOBS);
const ARGS = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
  "--disable-background-networking", "--disable-component-update", "--disable-sync"];
const TIMEOUT = 300000;

const median = (xs) => [...xs].sort((a, b) => a - b)[Math.floor(xs.length / 2)];

async function job_page(browser) {
  const page = await browser.newPage({ viewport: { width: 1400, height: 1000 } });
  page.setDefaultTimeout(TIMEOUT);
  await page.goto(`${URL}/jobs/${JOB}`);
  // Polled every animation frame; the page's own clock (ms since navigation) is read when it holds.
  const all = await page.waitForFunction((n) => {
    const box = document.querySelector("#plot-residual");
    return box && Number(box.dataset.points) === n ? performance.now() : false;
  }, N, { polling: "raf" });
  const result = await page.evaluate(() => ({
    first_plot_ms: performance.getEntriesByName("kontakt:first-plot")[0]?.startTime ?? null,
    history_loaded_ms: performance.getEntriesByName("kontakt:history-loaded")[0]?.startTime ?? null,
    increments_rows: Number(document.querySelector("#increments").dataset.rows),
    scripts_ready_ms: performance.getEntriesByType("navigation")[0].domContentLoadedEventEnd,
    heap_mb: performance.memory ? performance.memory.usedJSHeapSize / 2 ** 20 : null,
  }));
  result.all_points_ms = await all.jsonValue();
  // Still responsive: a cursor move over the plot updates the legend within a frame or two.
  const box = await page.locator("#plot-residual .u-over").boundingBox();
  const t0 = Date.now();
  await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
  await page.waitForFunction(() => /step \d+/.test(document.querySelector("#plot-residual .u-legend")?.textContent || ""));
  result.hover_ms = Date.now() - t0;
  await page.close();
  return result;
}

async function job_list(browser) {
  const page = await browser.newPage({ viewport: { width: 1400, height: 1000 } });
  page.setDefaultTimeout(TIMEOUT);
  await page.goto(`${URL}/?label=${encodeURIComponent(LIST_LABEL)}&limit=200`);
  await page.waitForFunction(() => performance.getEntriesByName("kontakt:list-shown").length === 1);
  const first_page_ms = await page.evaluate(() => performance.getEntriesByName("kontakt:list-shown")[0].startTime);
  let rows = await page.locator("#jobs tbody tr[data-id]").count();
  const t0 = Date.now();
  while (await page.locator("#next-page").isEnabled()) {
    const first = await page.getAttribute("#jobs tbody tr[data-id]", "data-id");
    await page.click("#next-page");
    await page.waitForFunction((id) => document.querySelector("#jobs tbody tr[data-id]")?.dataset.id !== id, first);
    rows += await page.locator("#jobs tbody tr[data-id]").count();
  }
  const paging_ms = Date.now() - t0;
  await page.close();
  return { first_page_ms, paging_ms, rows };
}

const browser = await chromium.launch({ executablePath: env.CHROMIUM, args: ARGS });
try {
  const pages = [];
  for (let i = 0; i < RUNS; i += 1) pages.push(await job_page(browser));
  const lists = [];
  for (let i = 0; i < RUNS; i += 1) lists.push(await job_list(browser));
  const out = {
    iterations: N,
    scripts_ready_ms: median(pages.map((p) => p.scripts_ready_ms)),
    first_plot_ms: median(pages.map((p) => p.first_plot_ms)),
    all_points_ms: median(pages.map((p) => p.all_points_ms)),
    history_loaded_ms: median(pages.map((p) => p.history_loaded_ms)),
    hover_ms: median(pages.map((p) => p.hover_ms)),
    heap_mb: median(pages.map((p) => p.heap_mb)),
    increments_rows: pages[0].increments_rows,
    jobs: N_JOBS,
    list_first_page_ms: median(lists.map((l) => l.first_page_ms)),
    list_paging_ms: median(lists.map((l) => l.paging_ms)),
    list_rows: lists[0].rows,
    runs: RUNS,
  };
  console.log(JSON.stringify(out));
} finally {
  await browser.close();
}
