// Tokenizes IL and ST text with the extension's TextMate grammars, as VS Code does (vscode-textmate on the
// Oniguruma WebAssembly build). Input: a language ('il' or 'st') and text. Output: per line, the tokens
// { text, scopes } (scopes outermost first). Run directly to print the tokens of a file:
//   node test/tokenize.js FILE.il|FILE.st
'use strict';

const fs = require('node:fs');
const path = require('node:path');
const vsctm = require('vscode-textmate');
const oniguruma = require('vscode-oniguruma');

const ROOT = path.join(__dirname, '..');
const SCOPES = {
  il: ['source.iec-il', 'syntaxes/iec-il.tmLanguage.json'],
  st: ['source.iec-st', 'syntaxes/iec-st.tmLanguage.json'],
};

let registryPromise;
function registry() {
  if (!registryPromise) {
    const wasm = fs.readFileSync(path.join(path.dirname(require.resolve('vscode-oniguruma')), 'onig.wasm'));
    const onigLib = oniguruma.loadWASM(wasm.buffer.slice(wasm.byteOffset, wasm.byteOffset + wasm.byteLength))
      .then(() => ({
        createOnigScanner: (sources) => new oniguruma.OnigScanner(sources),
        createOnigString: (s) => new oniguruma.OnigString(s),
      }));
    registryPromise = Promise.resolve(new vsctm.Registry({
      onigLib,
      loadGrammar: async (scopeName) => {
        const entry = Object.values(SCOPES).find(([scope]) => scope === scopeName);
        if (!entry) return null;
        const file = path.join(ROOT, entry[1]);
        return vsctm.parseRawGrammar(fs.readFileSync(file, 'utf8'), file);
      },
    }));
  }
  return registryPromise;
}

/** Tokens of every line of `text` in language `lang` ('il' | 'st'). */
async function tokenize(lang, text) {
  const grammar = await (await registry()).loadGrammar(SCOPES[lang][0]);
  if (!grammar) throw new Error(`no grammar for ${lang}`);
  let state = vsctm.INITIAL;
  const lines = [];
  for (const line of text.split(/\r?\n/)) {
    const r = grammar.tokenizeLine(line, state);
    lines.push(r.tokens.map((t) => ({ text: line.slice(t.startIndex, t.endIndex), scopes: t.scopes })));
    state = r.ruleStack;
  }
  return lines;
}

module.exports = { tokenize };

if (require.main === module) {
  const file = process.argv[2];
  if (!file) {
    console.error('usage: node test/tokenize.js FILE.il|FILE.st');
    process.exit(2);
  }
  const lang = path.extname(file).toLowerCase() === '.st' ? 'st' : 'il';
  tokenize(lang, fs.readFileSync(file, 'utf8')).then((lines) => {
    lines.forEach((tokens, i) => {
      for (const t of tokens) {
        if (t.text.trim()) console.log(`${i + 1}\t${JSON.stringify(t.text)}\t${t.scopes.slice(1).join(' ')}`);
      }
    });
  });
}
