// Headless Debian chromium (playwright-core) opens a page and reports its #pose text as it
// changes: one JSON line per distinct text, until `count` texts or an error text.
// Usage: node browser.cjs URL COUNT [HOST_RULES]
const { chromium } = require("playwright-core");

const [url, count, rules] = process.argv.slice(2);
const say = (step, value) => console.log(JSON.stringify({ step, value }));
(async () => {
  const args = [
    "--headless", "--no-sandbox", "--disable-gpu", "--disable-background-networking",
    "--disable-component-update", "--disable-sync", "--no-first-run",
  ];
  if (rules) args.push(`--host-resolver-rules=${rules}`);
  const browser = await chromium.launch({ executablePath: "/usr/bin/chromium", args });
  try {
    const page = await browser.newPage();
    page.on("pageerror", (err) => say("page_error", String(err)));
    await page.goto(url);
    const seen = [];
    const deadline = Date.now() + 20000;
    while (seen.length < Number(count) && Date.now() < deadline) {
      const text = await page.textContent("#pose");
      if (text !== "connecting" && text !== seen[seen.length - 1]) {
        seen.push(text);
        say("pose", text);
        if (text.startsWith("error")) break;
      }
      await page.waitForTimeout(20);
    }
    if (process.env.ROSX_SCREENSHOT) await page.screenshot({ path: process.env.ROSX_SCREENSHOT });
  } finally {
    await browser.close();
  }
})().catch((err) => {
  say("error", String(err));
  process.exit(1);
});
