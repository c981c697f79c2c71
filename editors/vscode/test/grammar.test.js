// The TextMate grammars, tokenized as VS Code does (vscode-textmate + Oniguruma): each case names a line of
// IL or ST, a piece of it, and the scope that piece must carry. The IL lines come from the repository's
// examples and the parser's sample (crates/il-frontend/tests/samples/rich.il); the ST lines from
// test/fixtures/sample.st.
'use strict';

const test = require('node:test');
const assert = require('node:assert/strict');
const fs = require('node:fs');
const path = require('node:path');
const { tokenize } = require('./tokenize');

const REPO = path.join(__dirname, '..', '..', '..');
const read = (rel) => fs.readFileSync(path.join(REPO, rel), 'utf8');

/** The scopes of the token that is exactly `piece`, the `nth` such token (0-based) in `line`. */
function scopesOf(tokens, piece, nth = 0) {
  const hits = tokens.filter((t) => t.text.trim() === piece);
  assert.ok(hits.length > nth, `no token ${JSON.stringify(piece)} in ${JSON.stringify(tokens.map((t) => t.text))}`);
  return hits[nth].scopes;
}

/** Asserts that in `text` (language `lang`), the line containing `where` has `piece` scoped `scope`. */
async function expectScope(lang, text, where, piece, scope, nth = 0) {
  const lines = await tokenize(lang, text);
  const sources = text.split(/\r?\n/);
  const index = sources.findIndex((l) => l.includes(where));
  assert.ok(index >= 0, `no line contains ${JSON.stringify(where)}`);
  const scopes = scopesOf(lines[index], piece, nth);
  assert.ok(scopes.includes(scope), `${JSON.stringify(piece)} in ${JSON.stringify(sources[index])}: ` +
    `expected ${scope}, got ${scopes.join(' ')}`);
}

/** Asserts that a file leaves no region open: a line `,` after it carries only the root scope. */
async function expectClosed(lang, text) {
  const lines = await tokenize(lang, `${text}\n,`);
  const last = lines[lines.length - 1];
  assert.deepEqual(last.map((t) => t.scopes), [[`source.iec-${lang}`]], 'a region is still open at the end');
}

const counter = read('examples/counter/counter.il');
const rich = read('crates/il-frontend/tests/samples/rich.il');
const paperB = read('examples/paper-b/paper_b.il');
const sampleSt = fs.readFileSync(path.join(__dirname, 'fixtures', 'sample.st'), 'utf8');

test('IL: examples/counter/counter.il', async () => {
  const cases = [
    ['(* A counter with a timer', '(*', 'punctuation.definition.comment.begin.iec'],
    ['100 ms after each edge', '100 ms after each edge. Run it with: ladderc run examples/counter/counter.il --stimulus ...',
      'comment.block.iec'],
    ['PROGRAM main', 'PROGRAM', 'storage.type.pou.iec'],
    ['PROGRAM main', 'main', 'entity.name.function.iec'],
    ['VAR', 'VAR', 'storage.type.var.iec'],
    ['pulse AT %IX0.0', 'pulse', 'variable.other.declaration.iec'],
    ['pulse AT %IX0.0', 'AT', 'storage.modifier.iec'],
    ['pulse AT %IX0.0', '%IX0.0', 'support.variable.address.iec'],
    ['pulse AT %IX0.0', 'BOOL', 'support.type.elementary.iec'],
    ['full AT %QX0.0', '%QX0.0', 'support.variable.address.iec'],
    ['counter : CTU', 'CTU', 'support.class.function-block.iec'],
    ['hold : TOF', 'TOF', 'support.class.function-block.iec'],
    ['count : INT', 'INT', 'support.type.elementary.iec'],
    ['END_VAR', 'END_VAR', 'storage.type.var.iec'],
    ['CAL counter(CU', 'CAL', 'keyword.control.call.il.iec'],
    ['CAL counter(CU', 'counter', 'entity.name.function.call.iec'],
    ['CAL counter(CU', 'CU', 'variable.parameter.iec'],
    ['CAL counter(CU', ':=', 'keyword.operator.assignment.iec'],
    ['CAL counter(CU', '5', 'constant.numeric.integer.decimal.iec'],
    ['LD counter.Q', 'LD', 'keyword.operator.il.iec'],
    ['ST full', 'ST', 'keyword.operator.il.iec'],
    ['PT := T#100ms', 'T#100ms', 'constant.numeric.duration.iec'],
    ['END_PROGRAM', 'END_PROGRAM', 'storage.type.pou.iec'],
  ];
  for (const [where, piece, scope] of cases) await expectScope('il', counter, where, piece, scope);
  await expectClosed('il', counter);
});

test('IL: operators with modifiers N and C, deferred `(`, jumps, calls, returns, labels', async () => {
  const cases = [
    ['ANDN stop', 'ANDN', 'keyword.operator.il.iec'],
    ['&N t2', '&N', 'keyword.operator.il.iec'],
    ['& t1', '&', 'keyword.operator.il.iec'],
    ['OR( running', 'OR', 'keyword.operator.il.iec'],
    ['OR( running', '(', 'keyword.operator.il.deferred.iec'],
    ['XORN( %IX0.2', 'XORN', 'keyword.operator.il.iec'],
    ['XORN( %IX0.2', '%IX0.2', 'support.variable.address.iec'],
    ['STN t1', 'STN', 'keyword.operator.il.iec'],
    ['S latch.S1', 'S', 'keyword.operator.il.iec'],
    ['R shared.x', 'R', 'keyword.operator.il.iec'],
    ['S1 latch', 'S1', 'keyword.operator.il.iec'],
    ['CLK tmr', 'CLK', 'keyword.operator.il.iec'],
    ['GE 1', 'GE', 'keyword.operator.il.iec'],
    ['JMPC done', 'JMPC', 'keyword.control.jump.il.iec'],
    ['JMPCN done', 'JMPCN', 'keyword.control.jump.il.iec'],
    ['JMPCN done', 'done', 'entity.name.label.iec'],
    ['JMP done', 'JMP', 'keyword.control.jump.il.iec'],
    ['done:', 'done', 'entity.name.label.iec'],
    ['CALC latch', 'CALC', 'keyword.control.call.il.iec'],
    ['CALCN tmr(running', 'CALCN', 'keyword.control.call.il.iec'],
    ['NOT ET => t2', 'NOT', 'keyword.operator.logical.iec'],
    ['NOT ET => t2', 'ET', 'variable.parameter.iec'],
    ['NOT ET => t2', '=>', 'keyword.operator.assignment.iec'],
    ['RETC', 'RETC', 'keyword.control.return.il.iec'],
    ['RETCN', 'RETCN', 'keyword.control.return.il.iec'],
    ['    RET', 'RET', 'keyword.control.return.il.iec'],
    ['FUNC Blink()', 'FUNC', 'keyword.control.call.il.iec'],
    ['INT_TO_REAL', 'INT_TO_REAL', 'entity.name.function.call.iec'],
    ['SEL 1, 2', 'SEL', 'entity.name.function.call.iec'],
    ['LIMIT(MN := 0', 'LIMIT', 'entity.name.function.call.iec'],
    ['LIMIT(MN := 0', 'MX', 'variable.parameter.iec'],
    ['end_lbl:', 'end_lbl', 'entity.name.label.iec'],
  ];
  for (const [where, piece, scope] of cases) await expectScope('il', rich, where, piece, scope);
  // `)` alone on a line closes a deferred operation (two of them in the sample)
  await expectScope('il', rich, '        )', ')', 'keyword.operator.il.deferred.iec');
  await expectClosed('il', rich);
});

test('IL: literals, strings, addresses, declarations (rich.il)', async () => {
  const cases = [
    ['counter : UDINT := 16#FFFF_FFFF', '16#FFFF_FFFF', 'constant.numeric.integer.hexadecimal.iec'],
    ['LD 2#1010', '2#1010', 'constant.numeric.integer.binary.iec'],
    ['ADD 8#17', '8#17', 'constant.numeric.integer.octal.iec'],
    ['LD 1.0E-5', '1.0E-5', 'constant.numeric.float.iec'],
    ['x, y : REAL := 0.5', '0.5', 'constant.numeric.float.iec'],
    ['x, y : REAL := 0.5', 'x, y', 'variable.other.declaration.iec'],
    ['factor : REAL := REAL#1.5', 'REAL', 'constant.numeric.typed.iec', 1],
    ['LD BOOL#TRUE', 'TRUE', 'constant.numeric.typed.iec'],
    ['LD UINT#16#a5', '16#a5', 'constant.numeric.typed.iec'],
    ['XOR TRUE', 'TRUE', 'constant.language.boolean.iec'],
    ['stop : BOOL := FALSE', 'FALSE', 'constant.language.boolean.iec'],
    ['tmr : TON := (PT := T#1h2m3.5s)', 'T#1h2m3.5s', 'constant.numeric.duration.iec'],
    ['neg : TIME := T#-1m30s', 'T#-1m30s', 'constant.numeric.duration.iec'],
    ['lt : LTIME := LTIME#1d2h', 'LTIME#1d2h', 'constant.numeric.duration.iec'],
    ['when : DT', 'DT#2001-04-09-11:36:15.20', 'constant.numeric.date-and-time.iec'],
    ['day : DATE', 'D#2001-04-09', 'constant.numeric.date.iec'],
    ['tod1 : TOD', 'TOD#11:36:15.2', 'constant.numeric.time-of-day.iec'],
    ['tod1 : TOD', 'tod1', 'variable.other.declaration.iec'],
    ['c : Color := Color#blue', 'blue', 'constant.other.enum.iec'],
    ["msg : STRING := 'it$'s", '$\'', 'constant.character.escape.iec'],
    ["msg : STRING := 'it$'s", '$$', 'constant.character.escape.iec'],
    ["msg : STRING := 'it$'s", '$N', 'constant.character.escape.iec'],
    ["msg : STRING := 'it$'s", 'it', 'string.quoted.single.iec'],
    ['wmsg : WSTRING', '$"', 'constant.character.escape.iec'],
    ['wmsg : WSTRING', 'say', 'string.quoted.double.iec'],
    ['lamp AT %QW3', '%QW3', 'support.variable.address.iec'],
    ['LD %MD10', '%MD10', 'support.variable.address.iec'],
    ['LD %MX4.23', '%MX4.23', 'support.variable.address.iec'],
    ['VAR_EXTERNAL CONSTANT', 'CONSTANT', 'storage.modifier.iec'],
    ['VAR_GLOBAL RETAIN', 'RETAIN', 'storage.modifier.iec'],
    ['Point : STRUCT', 'Point', 'entity.name.type.iec'],
    ['Row : ARRAY', 'ARRAY', 'keyword.other.iec'],
    ['TASK fast', 'T#10ms', 'constant.numeric.duration.iec'],
    ['TASK fast', 'INTERVAL', 'variable.parameter.iec'],
    ['RESOURCE Cpu ON PLC', 'RESOURCE', 'storage.type.pou.iec'],
  ];
  for (const [where, piece, scope, nth] of cases) await expectScope('il', rich, where, piece, scope, nth);
});

test('IL: PLCopen motion blocks and calls over several lines (paper_b.il)', async () => {
  await expectScope('il', paperB, 'move_a : MC_MoveLinearAbsolute', 'MC_MoveLinearAbsolute', 'support.class.motion.iec');
  await expectScope('il', paperB, 'power_x : MC_Power', 'MC_Power', 'support.class.motion.iec');
  // a continuation line of a CAL is arguments, not instructions
  await expectScope('il', paperB, 'Deceleration := 5.0, Jerk := 2.0, BufferMode := mcAborting',
    'Deceleration', 'variable.parameter.iec');
  await expectScope('il', paperB, 'TransitionParameter := 0.0)', ')', 'punctuation.section.arguments.end.iec');
  await expectClosed('il', paperB);
});

test('IL: keywords are case-insensitive and whole words', async () => {
  const text = [
    'program lower',
    'var',
    '    ldx : bool;',
    'end_var',
    '    ld ldx',
    '    andn( %ix0.1',
    '    )',
    '    st my_var',
    '    jmpc Done',
    '    ld t#1S',
    'end_program',
  ].join('\n');
  await expectScope('il', text, 'program lower', 'program', 'storage.type.pou.iec');
  await expectScope('il', text, 'ldx : bool', 'ldx', 'variable.other.declaration.iec');
  await expectScope('il', text, 'ldx : bool', 'bool', 'support.type.elementary.iec');
  await expectScope('il', text, 'ld ldx', 'ld', 'keyword.operator.il.iec');
  const lines = await tokenize('il', text);
  const operand = scopesOf(lines[4], 'ldx');
  assert.ok(!operand.some((s) => s.startsWith('keyword')), `operand ldx scoped ${operand.join(' ')}`);
  await expectScope('il', text, 'andn( %ix0.1', 'andn', 'keyword.operator.il.iec');
  await expectScope('il', text, 'andn( %ix0.1', '%ix0.1', 'support.variable.address.iec');
  await expectScope('il', text, 'jmpc Done', 'jmpc', 'keyword.control.jump.il.iec');
  await expectScope('il', text, 'ld t#1S', 't#1S', 'constant.numeric.duration.iec');
  await expectScope('il', text, 'end_program', 'end_program', 'storage.type.pou.iec');
  await expectClosed('il', text);
});

test('IL and ST: comments nest, // comments, pragmas', async () => {
  for (const lang of ['il', 'st']) {
    const text = '(* outer (* inner *) still comment *) LD x // tail\n{ pragma : here }';
    const lines = await tokenize(lang, text);
    assert.ok(scopesOf(lines[0], 'still comment').includes('comment.block.iec'), lang);
    assert.ok(scopesOf(lines[0], 'inner').filter((s) => s === 'comment.block.iec').length === 2, lang);
    assert.ok(scopesOf(lines[0], '// tail').includes('comment.line.double-slash.iec'), lang);
    assert.ok(scopesOf(lines[1], 'pragma : here').includes('meta.preprocessor.pragma.iec'), lang);
    // an unterminated comment runs on to the next lines
    const open = await tokenize(lang, '(* open\nLD x');
    assert.ok(scopesOf(open[1], 'LD x').includes('comment.block.iec'), lang);
  }
});

test('ST: statements, operators, calls (test/fixtures/sample.st)', async () => {
  const cases = [
    ['(* a nested comment *)', 'a nested comment', 'comment.block.iec'],
    ["{attribute 'qualified_only'}", "attribute 'qualified_only'", 'meta.preprocessor.pragma.iec'],
    ['FUNCTION_BLOCK Sorter', 'FUNCTION_BLOCK', 'storage.type.pou.iec'],
    ['FUNCTION_BLOCK Sorter', 'Sorter', 'entity.name.function.iec'],
    ['VAR_INPUT', 'VAR_INPUT', 'storage.type.var.iec'],
    ['VAR_OUTPUT', 'VAR_OUTPUT', 'storage.type.var.iec'],
    ['start AT %IX0.0 : BOOL', '%IX0.0', 'support.variable.address.iec'],
    ['speed : REAL := 1.5E3', '1.5E3', 'constant.numeric.float.iec'],
    ['word_out AT %QW3', '%QW3', 'support.variable.address.iec'],
    ['word_out AT %QW3', '16#FF', 'constant.numeric.integer.hexadecimal.iec'],
    ['positioner : MC_MoveAbsolute', 'MC_MoveAbsolute', 'support.class.motion.iec'],
    ['mask : BYTE := 2#1010', '2#1010', 'constant.numeric.integer.binary.iec'],
    ['i, n : INT := INT#5', 'i, n', 'variable.other.declaration.iec'],
    ['i, n : INT := INT#5', '5', 'constant.numeric.typed.iec'],
    ['hold : TOF := (PT := T#100ms)', 'T#100ms', 'constant.numeric.duration.iec'],
    ["msg : STRING[20] := 'it$'s $$5$N'", '$N', 'constant.character.escape.iec'],
    ["msg : STRING[20] := 'it$'s $$5$N'", 's', 'string.quoted.single.iec'],
    ['stamp : DT', 'DT#2024-01-31-12:00:00', 'constant.numeric.date-and-time.iec'],
    ['day : DATE', 'D#2024-01-31', 'constant.numeric.date.iec'],
    ['at_noon : TOD', 'TOD#12:00:00', 'constant.numeric.time-of-day.iec'],
    ['level AT %MD10', '%MD10', 'support.variable.address.iec'],
    ['counter(CU := start', 'counter', 'entity.name.function.call.iec'],
    ['counter(CU := start', 'CU', 'variable.parameter.iec'],
    ['counter(CU := start', 'FALSE', 'constant.language.boolean.iec'],
    ['hold(IN := counter.Q, Q => done)', '=>', 'keyword.operator.assignment.iec'],
    ['// a line comment', '// a line comment', 'comment.line.double-slash.iec'],
    ['IF counter.CV >= 5', 'IF', 'keyword.control.st.iec'],
    ['IF counter.CV >= 5', '>=', 'keyword.operator.comparison.iec'],
    ['IF counter.CV >= 5', 'AND', 'keyword.operator.logical.iec'],
    ['IF counter.CV >= 5', 'NOT', 'keyword.operator.logical.iec'],
    ['IF counter.CV >= 5', 'THEN', 'keyword.control.st.iec'],
    ['total := LIMIT(', 'LIMIT', 'support.function.iec'],
    ['total := LIMIT(', 'INT_TO_LREAL', 'support.function.iec'],
    ['total := LIMIT(', '*', 'keyword.operator.arithmetic.iec'],
    ['total := LIMIT(', ':=', 'keyword.operator.assignment.iec'],
    ['ELSIF state = running', 'ELSIF', 'keyword.control.st.iec'],
    ['ELSIF state = running', 'OR', 'keyword.operator.logical.iec'],
    ['END_IF;', 'END_IF', 'keyword.control.st.iec'],
    ['CASE n OF', 'CASE', 'keyword.control.st.iec'],
    ['n := n MOD 3', 'MOD', 'keyword.operator.arithmetic.iec'],
    ['END_CASE', 'END_CASE', 'keyword.control.st.iec'],
    ['FOR i := 1 TO 10 BY 2 DO', 'FOR', 'keyword.control.st.iec'],
    ['FOR i := 1 TO 10 BY 2 DO', 'TO', 'keyword.control.st.iec'],
    ['FOR i := 1 TO 10 BY 2 DO', 'BY', 'keyword.control.st.iec'],
    ['FOR i := 1 TO 10 BY 2 DO', 'DO', 'keyword.control.st.iec'],
    ['IF i > n THEN EXIT', 'EXIT', 'keyword.control.st.iec'],
    ['END_FOR', 'END_FOR', 'keyword.control.st.iec'],
    ['WHILE n < 10 DO', 'WHILE', 'keyword.control.st.iec'],
    ['END_WHILE', 'END_WHILE', 'keyword.control.st.iec'],
    ['REPEAT', 'REPEAT', 'keyword.control.st.iec'],
    ['UNTIL n <= 0', 'UNTIL', 'keyword.control.st.iec'],
    ['END_REPEAT', 'END_REPEAT', 'keyword.control.st.iec'],
    ['positioner(Axis := X1', 'positioner', 'entity.name.function.call.iec'],
    ['word_out := SHL(WORD#16#0F, 4)', 'SHL', 'support.function.iec'],
    ['word_out := SHL(WORD#16#0F, 4)', '16#0F', 'constant.numeric.typed.iec'],
    ['RETURN;', 'RETURN', 'keyword.control.st.iec'],
    ['RETURN;', ';', 'punctuation.terminator.statement.iec'],
    ['END_FUNCTION_BLOCK', 'END_FUNCTION_BLOCK', 'storage.type.pou.iec'],
  ];
  for (const [where, piece, scope] of cases) await expectScope('st', sampleSt, where, piece, scope);
  await expectClosed('st', sampleSt);
});

test('ST: IL operators are plain names in ST, and ST keywords are case-insensitive', async () => {
  const text = 'if ld > 1 then st := ld; end_if\nwhile x do x := false; end_while';
  await expectScope('st', text, 'if ld', 'if', 'keyword.control.st.iec');
  await expectScope('st', text, 'if ld', 'end_if', 'keyword.control.st.iec');
  await expectScope('st', text, 'while x', 'false', 'constant.language.boolean.iec');
  const lines = await tokenize('st', text);
  for (const t of lines[0]) {
    if (/^(?:ld|st)$/i.test(t.text.trim())) {
      assert.ok(!t.scopes.some((s) => s.startsWith('keyword')), `${t.text} scoped ${t.scopes.join(' ')}`);
    }
  }
});
