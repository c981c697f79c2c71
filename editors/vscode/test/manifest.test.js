// package.json's contributions are consistent: every file it names exists and parses, grammars and languages
// refer to each other, the regexes of language-configuration.json compile, and the grammars are the ones
// scripts/build-grammars.js writes.
'use strict';

const test = require('node:test');
const assert = require('node:assert/strict');
const fs = require('node:fs');
const path = require('node:path');
const { execFileSync } = require('node:child_process');

const ROOT = path.join(__dirname, '..');
const pkg = JSON.parse(fs.readFileSync(path.join(ROOT, 'package.json'), 'utf8'));
const file = (rel) => path.join(ROOT, rel);
const readJson = (rel) => JSON.parse(fs.readFileSync(file(rel), 'utf8'));

test('package.json: main, engines, activation', () => {
  assert.equal(pkg.name, 'ladderc');
  assert.ok(fs.existsSync(file(pkg.main)), `main ${pkg.main} is missing`);
  assert.match(pkg.engines.vscode, /^\^1\.\d+\.\d+$/);
  // vscode-languageclient states the oldest VS Code it supports; ours must not be older
  const client = readJson('node_modules/vscode-languageclient/package.json');
  const minor = (range) => Number(range.match(/^\^1\.(\d+)/)[1]);
  assert.ok(minor(pkg.engines.vscode) >= minor(client.engines.vscode),
    `engines.vscode ${pkg.engines.vscode} is older than vscode-languageclient's ${client.engines.vscode}`);
  for (const lang of ['iec-il', 'iec-st']) {
    assert.ok(pkg.activationEvents.includes(`onLanguage:${lang}`), `no activation on ${lang}`);
  }
});

test('package.json: languages and their configuration', () => {
  const languages = pkg.contributes.languages;
  assert.deepEqual(languages.map((l) => l.id).sort(), ['iec-il', 'iec-st']);
  assert.deepEqual(languages.find((l) => l.id === 'iec-il').extensions, ['.il']);
  assert.deepEqual(languages.find((l) => l.id === 'iec-st').extensions, ['.st']);
  for (const lang of languages) {
    assert.ok(fs.existsSync(file(lang.configuration)), `${lang.configuration} is missing`);
    const conf = readJson(lang.configuration);
    assert.equal(conf.comments.lineComment, '//');
    assert.deepEqual(conf.comments.blockComment, ['(*', '*)']);
    assert.ok(conf.brackets.some(([a, b]) => a === '(' && b === ')'));
    assert.ok(conf.autoClosingPairs.some((p) => p.open === "'" && p.close === "'"));
    // VS Code compiles these with JavaScript's RegExp: they must compile there
    const regexes = [conf.wordPattern, conf.indentationRules.increaseIndentPattern,
      conf.indentationRules.decreaseIndentPattern];
    for (const r of regexes) new RegExp(r.pattern, r.flags);
    const word = new RegExp(`^(?:${conf.wordPattern.pattern})$`, conf.wordPattern.flags);
    for (const w of ['%IX0.1', '%qw3', 'T#100ms', '16#FF', 'counter_1']) assert.match(w, word);
    const indent = new RegExp(conf.indentationRules.increaseIndentPattern.pattern,
      conf.indentationRules.increaseIndentPattern.flags);
    assert.match('    IF x THEN', indent);
    assert.match('var_input', indent);
    assert.doesNotMatch('IF x THEN y := 1; END_IF', indent);
  }
});

test('package.json: grammars exist, parse, and match their languages', () => {
  const ids = new Set(pkg.contributes.languages.map((l) => l.id));
  assert.equal(pkg.contributes.grammars.length, 2);
  for (const g of pkg.contributes.grammars) {
    assert.ok(ids.has(g.language), `grammar for unknown language ${g.language}`);
    assert.ok(fs.existsSync(file(g.path)), `${g.path} is missing`);
    const grammar = readJson(g.path);
    assert.equal(grammar.scopeName, g.scopeName);
    assert.equal(g.scopeName, `source.${g.language}`);
    // every #name a grammar includes is in its repository
    const text = fs.readFileSync(file(g.path), 'utf8');
    for (const [, name] of text.matchAll(/"include": "#([^"]+)"/g)) {
      assert.ok(grammar.repository[name], `${g.path} includes #${name}, which it does not define`);
    }
  }
});

test('package.json: the ladderc.path setting and the restart command', () => {
  const props = pkg.contributes.configuration.properties;
  assert.equal(props['ladderc.path'].type, 'string');
  assert.equal(props['ladderc.path'].default, 'ladderc');
  assert.ok(props['ladderc.trace.server'].enum.includes('verbose'));
  const commands = pkg.contributes.commands.map((c) => c.command);
  assert.deepEqual(commands, ['ladderc.restartServer']);
  const source = fs.readFileSync(file(pkg.main), 'utf8');
  for (const c of commands) assert.ok(source.includes(`'${c}'`), `${pkg.main} does not register ${c}`);
});

test('the committed grammars are what scripts/build-grammars.js writes', () => {
  // exits non-zero (and execFileSync throws) when a grammar is stale
  execFileSync(process.execPath, [file('scripts/build-grammars.js'), '--check'], { cwd: ROOT, stdio: 'pipe' });
});

test('node_modules and packaged .vsix files are not committed', () => {
  const ignore = fs.readFileSync(file('.gitignore'), 'utf8').split('\n');
  assert.ok(ignore.includes('node_modules/'));
  assert.ok(ignore.includes('*.vsix'));
});
