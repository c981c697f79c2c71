#!/usr/bin/env node
// Writes the TextMate grammars syntaxes/iec-il.tmLanguage.json and syntaxes/iec-st.tmLanguage.json.
//
// Input: the rule tables below (IEC 61131-3 keywords, literals, addresses; the rules both languages share are
// written once). Output: the two JSON grammars, byte-identical on every run. `npm run build` writes them;
// `node scripts/build-grammars.js --check` (run by `npm test`) fails when the committed files are stale.
// Invariants: every regex starts with (?i) (IEC keywords and literals are case-insensitive); a word list
// matches whole words only.
'use strict';

const fs = require('node:fs');
const path = require('node:path');

const words = (list) => list.join('|');
const ID = '[A-Za-z_][A-Za-z0-9_]*';

// ---- word lists -------------------------------------------------------------------------------------------
const POU = [
  'END_FUNCTION_BLOCK', 'FUNCTION_BLOCK', 'END_FUNCTION', 'FUNCTION', 'END_PROGRAM', 'PROGRAM',
  'END_CONFIGURATION', 'CONFIGURATION', 'END_RESOURCE', 'RESOURCE', 'END_ACTION', 'ACTION',
  'END_TRANSITION', 'TRANSITION', 'INITIAL_STEP', 'END_STEP', 'STEP', 'END_METHOD', 'METHOD',
  'END_INTERFACE', 'INTERFACE', 'TASK',
];
const POU_NAMED = ['FUNCTION_BLOCK', 'FUNCTION', 'PROGRAM', 'CONFIGURATION', 'RESOURCE', 'ACTION', 'TRANSITION',
  'INITIAL_STEP', 'STEP', 'METHOD', 'INTERFACE', 'TASK'];
const VAR_BLOCKS = ['VAR_INPUT', 'VAR_OUTPUT', 'VAR_IN_OUT', 'VAR_TEMP', 'VAR_GLOBAL', 'VAR_EXTERNAL', 'VAR_ACCESS',
  'VAR_CONFIG', 'VAR_STAT', 'VAR'];
const MODIFIERS = ['CONSTANT', 'RETAIN', 'NON_RETAIN', 'PERSISTENT', 'AT', 'R_EDGE', 'F_EDGE', 'READ_ONLY',
  'READ_WRITE', 'EXTENDS', 'IMPLEMENTS', 'ABSTRACT', 'FINAL', 'PUBLIC', 'PRIVATE', 'PROTECTED', 'INTERNAL'];
const OTHER_KEYWORDS = ['ARRAY', 'OF', 'REF_TO', 'POINTER', 'TO', 'ON', 'WITH', 'FROM', 'END_STRUCT', 'STRUCT',
  'END_TYPE', 'TYPE'];
const ELEMENTARY = [
  'BOOL', 'SINT', 'INT', 'DINT', 'LINT', 'USINT', 'UINT', 'UDINT', 'ULINT', 'REAL', 'LREAL', 'BYTE', 'WORD',
  'DWORD', 'LWORD', 'LTIME_OF_DAY', 'TIME_OF_DAY', 'LTIME', 'TIME', 'LDATE_AND_TIME', 'DATE_AND_TIME', 'LDATE',
  'DATE', 'LTOD', 'TOD', 'LDT', 'DT', 'WSTRING', 'STRING', 'WCHAR', 'CHAR',
  'ANY_DERIVED', 'ANY_ELEMENTARY', 'ANY_MAGNITUDE', 'ANY_NUM', 'ANY_REAL', 'ANY_INT', 'ANY_BIT', 'ANY_STRING',
  'ANY_DATE', 'ANY_DURATION', 'ANY_CHARS', 'ANY_CHAR', 'ANY',
];
const NUMERIC_TYPES = ['BOOL', 'SINT', 'INT', 'DINT', 'LINT', 'USINT', 'UINT', 'UDINT', 'ULINT', 'REAL', 'LREAL',
  'BYTE', 'WORD', 'DWORD', 'LWORD'];
const STANDARD_FBS = ['(?:L?TON|L?TOF|L?TP|CTUD|CTU|CTD)(?:_(?:INT|DINT|LINT|UDINT|ULINT))?', 'R_TRIG', 'F_TRIG',
  'SR', 'RS'];
// IL operators (IEC 61131-3 table 68 and 69): the N modifier is part of the word; `(` defers the operation.
const IL_OPERATORS = ['LDN', 'LD', 'STN', 'ST', 'S1', 'R1', 'S', 'R', 'ANDN', 'AND', 'ORN', 'OR', 'XORN', 'XOR',
  'NOT', 'ADD', 'SUB', 'MUL', 'DIV', 'MOD', 'GT', 'GE', 'EQ', 'NE', 'LE', 'LT', 'CLK', 'CU', 'CD', 'PV', 'IN',
  'PT'];
const IL_JUMPS = ['JMPCN', 'JMPNC', 'JMPC', 'JMP'];
const IL_CALLS = ['CALCN', 'CALNC', 'CALC', 'CAL'];
const IL_RETURNS = ['RETCN', 'RETNC', 'RETC', 'RET'];
const ST_CONTROL = ['END_IF', 'ELSIF', 'ELSE', 'IF', 'THEN', 'END_CASE', 'CASE', 'END_FOR', 'FOR', 'TO', 'BY', 'DO',
  'END_WHILE', 'WHILE', 'END_REPEAT', 'REPEAT', 'UNTIL', 'EXIT', 'CONTINUE', 'RETURN'];
const ST_WORD_OPERATORS = ['AND_THEN', 'OR_ELSE', 'AND', 'OR', 'XOR', 'NOT'];
const STANDARD_FUNCTIONS = ['ABS', 'SQRT', 'LN', 'LOG', 'EXP', 'SIN', 'COS', 'TAN', 'ASIN', 'ACOS', 'ATAN2',
  'ATAN', 'EXPT', 'MOVE', 'SHL', 'SHR', 'ROL', 'ROR', 'SEL', 'MAX', 'MIN', 'LIMIT', 'MUX', 'LEN', 'LEFT',
  'RIGHT', 'MID', 'CONCAT', 'INSERT', 'DELETE', 'REPLACE', 'FIND', 'TRUNC', 'ADD', 'SUB', 'MUL', 'DIV',
  '[A-Z]+_TO_[A-Z]+', 'TO_[A-Z]+'];

// Every keyword; an identifier at the start of an IL instruction that is none of them is a function name.
const ALL_KEYWORDS = [...POU, ...VAR_BLOCKS, 'END_VAR', ...MODIFIERS, ...OTHER_KEYWORDS, ...IL_OPERATORS,
  ...IL_JUMPS, ...IL_CALLS, ...IL_RETURNS, 'FUNC', 'TRUE', 'FALSE'];

// ---- rules both languages share ---------------------------------------------------------------------------
const common = {
  comments: {
    patterns: [
      { include: '#block-comment' },
      { name: 'comment.line.double-slash.iec', match: '//.*$' },
    ],
  },
  // Nested, as ladderc reads them.
  'block-comment': {
    name: 'comment.block.iec',
    begin: '\\(\\*',
    end: '\\*\\)',
    beginCaptures: { 0: { name: 'punctuation.definition.comment.begin.iec' } },
    endCaptures: { 0: { name: 'punctuation.definition.comment.end.iec' } },
    patterns: [{ include: '#block-comment' }],
  },
  pragmas: {
    name: 'meta.preprocessor.pragma.iec',
    begin: '\\{',
    end: '\\}',
    beginCaptures: { 0: { name: 'punctuation.definition.pragma.begin.iec' } },
    endCaptures: { 0: { name: 'punctuation.definition.pragma.end.iec' } },
  },
  strings: {
    patterns: [
      {
        name: 'string.quoted.single.iec',
        begin: "'",
        end: "'",
        beginCaptures: { 0: { name: 'punctuation.definition.string.begin.iec' } },
        endCaptures: { 0: { name: 'punctuation.definition.string.end.iec' } },
        patterns: [
          { name: 'constant.character.escape.iec', match: "(?i)\\$(?:[$'LNPRT]|[0-9A-F]{2})" },
          { name: 'invalid.illegal.escape.iec', match: '\\$.?' },
        ],
      },
      {
        name: 'string.quoted.double.iec',
        begin: '"',
        end: '"',
        beginCaptures: { 0: { name: 'punctuation.definition.string.begin.iec' } },
        endCaptures: { 0: { name: 'punctuation.definition.string.end.iec' } },
        patterns: [
          { name: 'constant.character.escape.iec', match: '(?i)\\$(?:[$"LNPRT]|[0-9A-F]{4})' },
          { name: 'invalid.illegal.escape.iec', match: '\\$.?' },
        ],
      },
    ],
  },
  addresses: {
    // %IX0.1, %QW3, %MD10, %I* (IEC 61131-3 6.5.5)
    name: 'support.variable.address.iec',
    match: '(?i)%[IQM](?:[XBWDL]?[0-9]+(?:\\.[0-9]+)*|[XBWDL]?\\*)',
  },
  literals: {
    patterns: [
      {
        name: 'constant.numeric.date-and-time.iec',
        match: '(?i)\\b(?:L?DATE_AND_TIME|L?DT)#[0-9]+-[0-9]+-[0-9]+-[0-9]+:[0-9]+(?::[0-9]+(?:\\.[0-9]+)?)?',
      },
      {
        name: 'constant.numeric.time-of-day.iec',
        match: '(?i)\\b(?:L?TIME_OF_DAY|L?TOD)#[0-9]+:[0-9]+(?::[0-9]+(?:\\.[0-9]+)?)?',
      },
      { name: 'constant.numeric.date.iec', match: '(?i)\\b(?:L?DATE|L?D)#[0-9]+-[0-9]+-[0-9]+' },
      {
        name: 'constant.numeric.duration.iec',
        match: '(?i)\\b(?:L?TIME|L?T)#[+-]?(?:[0-9][0-9_]*(?:\\.[0-9]+)?(?:MS|US|NS|D|H|M|S)_?)+',
      },
      {
        name: 'constant.numeric.typed.iec',
        match: `(?i)\\b(${words(NUMERIC_TYPES)})(#)(?:[0-9]+#[0-9A-F_]+|[+-]?[0-9][0-9_]*(?:\\.[0-9_]+)?` +
          '(?:E[+-]?[0-9]+)?|TRUE|FALSE)\\b',
        captures: { 1: { name: 'support.type.elementary.iec' }, 2: { name: 'punctuation.separator.type.iec' } },
      },
      {
        // STRING#'text': the type here, the string itself by #strings
        match: '(?i)\\b(W?STRING|W?CHAR)(#)(?=[\'"])',
        captures: { 1: { name: 'support.type.elementary.iec' }, 2: { name: 'punctuation.separator.type.iec' } },
      },
      { name: 'constant.numeric.integer.binary.iec', match: '\\b2#[01_]+\\b' },
      { name: 'constant.numeric.integer.octal.iec', match: '\\b8#[0-7_]+\\b' },
      { name: 'constant.numeric.integer.hexadecimal.iec', match: '(?i)\\b16#[0-9A-F_]+\\b' },
      { name: 'constant.numeric.float.iec', match: '(?i)\\b[0-9][0-9_]*(?:\\.[0-9][0-9_]*(?:E[+-]?[0-9]+)?|E[+-]?[0-9]+)\\b' },
      { name: 'constant.numeric.integer.decimal.iec', match: '\\b[0-9][0-9_]*\\b' },
      { name: 'constant.language.boolean.iec', match: '(?i)\\b(?:TRUE|FALSE)\\b' },
      {
        // Color#red
        name: 'constant.other.enum.iec',
        match: `(?i)\\b(${ID})(#)(${ID})\\b`,
        captures: { 1: { name: 'entity.name.type.enum.iec' }, 2: { name: 'punctuation.separator.type.iec' } },
      },
    ],
  },
  types: {
    patterns: [
      { name: 'support.type.elementary.iec', match: `(?i)\\b(?:${words(ELEMENTARY)})\\b` },
      { name: 'support.class.function-block.iec', match: `(?i)\\b(?:${words(STANDARD_FBS)})\\b` },
      { name: 'support.class.motion.iec', match: '(?i)\\b(?:MC_[A-Z0-9_]+|AXIS_REF|AXES_GROUP_REF)\\b' },
    ],
  },
  keywords: {
    patterns: [
      {
        match: `(?i)\\b(${words(POU_NAMED)})\\b(?:\\s+(?!(?:RETAIN|NON_RETAIN|CONSTANT)\\b)(${ID}))?`,
        captures: { 1: { name: 'storage.type.pou.iec' }, 2: { name: 'entity.name.function.iec' } },
      },
      { name: 'storage.type.pou.iec', match: `(?i)\\b(?:${words(POU)})\\b` },
      { name: 'storage.type.var.iec', match: `(?i)\\b(?:${words(VAR_BLOCKS)}|END_VAR)\\b` },
      { name: 'storage.modifier.iec', match: `(?i)\\b(?:${words(MODIFIERS)})\\b` },
      { name: 'keyword.other.iec', match: `(?i)\\b(?:${words(OTHER_KEYWORDS)})\\b` },
    ],
  },
  assignment: {
    patterns: [
      { name: 'keyword.operator.assignment.iec', match: ':=' },
      { name: 'keyword.operator.assignment.output.iec', match: '=>' },
    ],
  },
  // VAR ... END_VAR: declarations (names, AT addresses, types, initial values); no statements inside.
  'var-block': {
    name: 'meta.declaration.var.iec',
    begin: `(?i)\\b(${words(VAR_BLOCKS)})\\b`,
    end: '(?i)\\b(END_VAR)\\b',
    beginCaptures: { 1: { name: 'storage.type.var.iec' } },
    endCaptures: { 1: { name: 'storage.type.var.iec' } },
    patterns: [
      { include: '#comments' },
      { include: '#pragmas' },
      { include: '#declared-names' },
      { include: '#strings' },
      { include: '#addresses' },
      { include: '#literals' },
      { include: '#keywords' },
      { include: '#types' },
      { include: '#assignment' },
    ],
  },
  // `a, b : INT` / `pulse AT %IX0.0 : BOOL`: the declared names, at the start of a line or after a `;`
  'declared-names': {
    match: `(?i)(?:^|(?<=;))\\s*(${ID}(?:\\s*,\\s*${ID})*)(?=\\s*(?::(?!=)|\\bAT\\b))`,
    captures: { 1: { name: 'variable.other.declaration.iec' } },
  },
  // TYPE ... END_TYPE: a type name before its `:`; STRUCT fields are declarations.
  'type-block': {
    name: 'meta.declaration.type.iec',
    begin: '(?i)\\b(TYPE)\\b',
    end: '(?i)\\b(END_TYPE)\\b',
    beginCaptures: { 1: { name: 'storage.type.pou.iec' } },
    endCaptures: { 1: { name: 'storage.type.pou.iec' } },
    patterns: [
      { include: '#comments' },
      { include: '#pragmas' },
      {
        name: 'meta.declaration.struct.iec',
        begin: '(?i)\\b(STRUCT)\\b',
        end: '(?i)\\b(END_STRUCT)\\b',
        beginCaptures: { 1: { name: 'keyword.other.iec' } },
        endCaptures: { 1: { name: 'keyword.other.iec' } },
        patterns: [
          { include: '#comments' },
          { include: '#pragmas' },
          { include: '#declared-names' },
          { include: '#strings' },
          { include: '#addresses' },
          { include: '#literals' },
          { include: '#keywords' },
          { include: '#types' },
          { include: '#assignment' },
        ],
      },
      { name: 'entity.name.type.iec', match: `(?i)^\\s*(${ID})(?=\\s*:(?!=))` },
      { include: '#strings' },
      { include: '#literals' },
      { include: '#keywords' },
      { include: '#types' },
      { include: '#assignment' },
    ],
  },
  parens: {
    begin: '\\(',
    end: '\\)',
    patterns: [{ include: '#call-arguments' }],
  },
  // The inside of a call's parentheses: parameter names before := and =>, then any value.
  'call-arguments': {
    patterns: [
      { include: '#comments' },
      { include: '#pragmas' },
      {
        match: `(?i)\\b(?:(NOT)\\s+)?(${ID})\\s*(:=|=>)`,
        captures: {
          1: { name: 'keyword.operator.logical.iec' },
          2: { name: 'variable.parameter.iec' },
          3: { name: 'keyword.operator.assignment.iec' },
        },
      },
      { include: '#parens' },
      { include: '#strings' },
      { include: '#addresses' },
      { include: '#literals' },
      { include: '#types' },
      { name: 'keyword.operator.logical.iec', match: `(?i)\\b(?:${words(ST_WORD_OPERATORS)})\\b` },
      { include: '#st-operators' },
    ],
  },
  'st-operators': {
    patterns: [
      { include: '#assignment' },
      { name: 'keyword.operator.comparison.iec', match: '<>|<=|>=|=|<|>' },
      { name: 'keyword.operator.arithmetic.iec', match: '(?i)\\*\\*|[-+*/]|\\bMOD\\b' },
      { name: 'keyword.operator.logical.iec', match: '&' },
    ],
  },
};

// ---- IL ---------------------------------------------------------------------------------------------------
// An instruction is `[label:] operator [operand]` on one line (IEC 61131-3 7.2).
const LABEL = `(?:(${ID})\\s*(:)(?!=)\\s*)?`;
const labelCaptures = { 1: { name: 'entity.name.label.iec' }, 2: { name: 'punctuation.separator.label.iec' } };
const il = {
  $schema: 'https://raw.githubusercontent.com/martinring/tmlanguage/master/tmlanguage.json',
  name: 'IEC 61131-3 Instruction List',
  scopeName: 'source.iec-il',
  fileTypes: ['il'],
  patterns: [
    { include: '#comments' },
    { include: '#pragmas' },
    { include: '#var-block' },
    { include: '#type-block' },
    { include: '#instructions' },
    { include: '#keywords' },
    { include: '#strings' },
    { include: '#addresses' },
    { include: '#literals' },
    { include: '#types' },
    { include: '#assignment' },
    { include: '#parens' },
  ],
  repository: {
    ...common,
    instructions: {
      patterns: [
        {
          // CAL fb(IN := x, ...), possibly over several lines
          begin: `(?i)^\\s*${LABEL}\\b(${words(IL_CALLS)}|FUNC)\\s+(${ID}(?:\\.${ID})*)\\s*(\\()`,
          end: '\\)',
          beginCaptures: {
            ...labelCaptures,
            3: { name: 'keyword.control.call.il.iec' },
            4: { name: 'entity.name.function.call.iec' },
            5: { name: 'punctuation.section.arguments.begin.iec' },
          },
          endCaptures: { 0: { name: 'punctuation.section.arguments.end.iec' } },
          patterns: [{ include: '#call-arguments' }],
        },
        {
          match: `(?i)^\\s*${LABEL}\\b(${words(IL_CALLS)}|FUNC)\\b(?:\\s+(${ID}(?:\\.${ID})*))?`,
          captures: {
            ...labelCaptures,
            3: { name: 'keyword.control.call.il.iec' },
            4: { name: 'entity.name.function.call.iec' },
          },
        },
        {
          match: `(?i)^\\s*${LABEL}\\b(${words(IL_JUMPS)})\\b(?:\\s+(${ID}))?`,
          captures: {
            ...labelCaptures,
            3: { name: 'keyword.control.jump.il.iec' },
            4: { name: 'entity.name.label.iec' },
          },
        },
        {
          match: `(?i)^\\s*${LABEL}\\b(${words(IL_RETURNS)})\\b`,
          captures: { ...labelCaptures, 3: { name: 'keyword.control.return.il.iec' } },
        },
        {
          match: `(?i)^\\s*${LABEL}(?:\\b(${words(IL_OPERATORS)})\\b|(&N?)(?![A-Za-z0-9_]))(?:\\s*(\\())?`,
          captures: {
            ...labelCaptures,
            3: { name: 'keyword.operator.il.iec' },
            4: { name: 'keyword.operator.il.iec' },
            5: { name: 'keyword.operator.il.deferred.iec' },
          },
        },
        {
          // the `)` that ends a deferred operation
          match: `^\\s*${LABEL}(\\))`,
          captures: { ...labelCaptures, 3: { name: 'keyword.operator.il.deferred.iec' } },
        },
        {
          // LIMIT(MN := 0, IN := i, MX := 10): a function with formal arguments
          begin: `(?i)^\\s*${LABEL}\\b(?!(?:${words(ALL_KEYWORDS)})\\b)(${ID})\\s*(\\()`,
          end: '\\)',
          beginCaptures: {
            ...labelCaptures,
            3: { name: 'entity.name.function.call.iec' },
            4: { name: 'punctuation.section.arguments.begin.iec' },
          },
          endCaptures: { 0: { name: 'punctuation.section.arguments.end.iec' } },
          patterns: [{ include: '#call-arguments' }],
        },
        {
          // SEL 1, 2 / INT_TO_REAL: a function as operator
          match: `(?i)^\\s*${LABEL}\\b(?!(?:${words(ALL_KEYWORDS)})\\b)(${ID})\\b(?!\\s*:(?!=))`,
          captures: { ...labelCaptures, 3: { name: 'entity.name.function.call.iec' } },
        },
        {
          // a label alone on its line
          match: `(?i)^\\s*(?!(?:${words(ALL_KEYWORDS)})\\b)(${ID})\\s*(:)(?!=)`,
          captures: labelCaptures,
        },
      ],
    },
  },
};

// ---- ST ---------------------------------------------------------------------------------------------------
const st = {
  $schema: 'https://raw.githubusercontent.com/martinring/tmlanguage/master/tmlanguage.json',
  name: 'IEC 61131-3 Structured Text',
  scopeName: 'source.iec-st',
  fileTypes: ['st'],
  patterns: [
    { include: '#comments' },
    { include: '#pragmas' },
    { include: '#var-block' },
    { include: '#type-block' },
    { include: '#statements' },
  ],
  repository: {
    ...common,
    statements: {
      patterns: [
        { include: '#comments' },
        { include: '#pragmas' },
        { name: 'keyword.control.st.iec', match: `(?i)\\b(?:${words(ST_CONTROL)})\\b` },
        { include: '#keywords' },
        { name: 'keyword.operator.logical.iec', match: `(?i)\\b(?:${words(ST_WORD_OPERATORS)})\\b` },
        { include: '#strings' },
        { include: '#addresses' },
        { include: '#literals' },
        { include: '#types' },
        {
          // calls of standard functions, user functions and FB instances
          begin: `(?i)\\b(?:(${words(STANDARD_FUNCTIONS)})|(${ID}))\\s*(\\()`,
          end: '\\)',
          beginCaptures: {
            1: { name: 'support.function.iec' },
            2: { name: 'entity.name.function.call.iec' },
            3: { name: 'punctuation.section.arguments.begin.iec' },
          },
          endCaptures: { 0: { name: 'punctuation.section.arguments.end.iec' } },
          patterns: [{ include: '#call-arguments' }, { include: '#statements' }],
        },
        { include: '#st-operators' },
        { name: 'punctuation.terminator.statement.iec', match: ';' },
        {
          begin: '\\(',
          end: '\\)',
          patterns: [{ include: '#statements' }],
        },
      ],
    },
  },
};

// ---- write or check ---------------------------------------------------------------------------------------
const outputs = [
  [path.join(__dirname, '..', 'syntaxes', 'iec-il.tmLanguage.json'), il],
  [path.join(__dirname, '..', 'syntaxes', 'iec-st.tmLanguage.json'), st],
];
const check = process.argv.includes('--check');
let stale = 0;
for (const [file, grammar] of outputs) {
  const text = JSON.stringify(grammar, null, 2) + '\n';
  if (check) {
    const old = fs.existsSync(file) ? fs.readFileSync(file, 'utf8') : '';
    if (old !== text) {
      console.error(`${path.relative(process.cwd(), file)} is stale: run \`npm run build\``);
      stale++;
    }
  } else {
    fs.mkdirSync(path.dirname(file), { recursive: true });
    fs.writeFileSync(file, text);
    console.log(`wrote ${path.relative(process.cwd(), file)}`);
  }
}
process.exitCode = stale ? 1 : 0;
