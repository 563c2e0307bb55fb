// Every equation of the built HTML pages typesets with Debian's KaTeX
// (throwOnError: a LaTeX mistake fails here, not in front of the class).
//   node katex_check.js KATEX_JS PAGE.html...
const katex = require(process.argv[2]);
let count = 0, bad = 0;
const unescape = (s) => s.replace(/&lt;/g, '<').replace(/&gt;/g, '>').replace(/&quot;/g, '"').replace(/&amp;/g, '&');
for (const page of process.argv.slice(3)) {
  const html = require('fs').readFileSync(page, 'utf8');
  for (const m of html.matchAll(/<x-equation( type="display")?>([\s\S]*?)<\/x-equation>/g)) {
    ++count;
    try {
      katex.renderToString(unescape(m[2]), {displayMode: !!m[1], throwOnError: true});
    } catch (e) {
      ++bad;
      console.log(`FAIL ${page}: ${e.message}`);
    }
  }
}
console.log(`${count - bad} of ${count} equations typeset`);
process.exit(bad || count === 0 ? 1 : 0);
