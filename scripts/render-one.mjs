import { chromium } from 'playwright-core';
import { readFileSync } from 'node:fs';
import { CHROMIUM } from '../tests/browser/chromium.mjs';
const browser = await chromium.launch(CHROMIUM);
const page = await browser.newPage({ viewport: { width: 1200, height: 1200 } });
await page.setContent(`<style>body{margin:0}svg{width:1200px;height:1200px}</style>${readFileSync(process.argv[2],'utf8')}`);
await page.screenshot({ path: process.argv[3] });
await browser.close();
