// The ladderc VS Code extension: starts `ladderc lsp` (the language server, on stdio) for IEC 61131-3 IL
// (`iec-il`), ST (`iec-st`) and PLCopen TC6 XML files, and restarts it when `ladderc.path` changes.
// Input: the `ladderc.path` setting (default `ladderc`, looked up on PATH). Output: a running language client.
// Invariants: at most one server process at a time; deactivate() stops it.
'use strict';

const vscode = require('vscode');
const { LanguageClient } = require('vscode-languageclient/node');

/** The files the server is told about: IL and ST by language, PLCopen projects by file name. */
const DOCUMENT_SELECTOR = [
  { scheme: 'file', language: 'iec-il' },
  { scheme: 'file', language: 'iec-st' },
  { scheme: 'file', pattern: '**/*.xml' },
  { scheme: 'untitled', language: 'iec-il' },
  { scheme: 'untitled', language: 'iec-st' },
];

/** How the server is started: `<ladderc.path> lsp`, stdio transport (the default for a command). */
function serverOptions(config) {
  const command = (config.get('path') || 'ladderc').trim() || 'ladderc';
  return { command, args: ['lsp'], options: { env: process.env } };
}

function clientOptions() {
  return {
    documentSelector: DOCUMENT_SELECTOR,
    synchronize: {
      // Project-aware diagnostics: the server rechecks when an axes file or a template changes.
      fileEvents: [
        vscode.workspace.createFileSystemWatcher('**/*.axes.json'),
        vscode.workspace.createFileSystemWatcher('**/templates/**'),
      ],
    },
  };
}

let client;

async function start() {
  const config = vscode.workspace.getConfiguration('ladderc');
  client = new LanguageClient('ladderc', 'ladderc', serverOptions(config), clientOptions());
  try {
    await client.start();
  } catch (err) {
    const command = serverOptions(config).command;
    vscode.window.showErrorMessage(
      `ladderc: could not start \`${command} lsp\` (${err && err.message ? err.message : err}). ` +
        'Install ladderc (cargo install --path crates/ladderc) or set `ladderc.path`.');
  }
}

async function stop() {
  if (!client) return;
  const old = client;
  client = undefined;
  try {
    await old.stop();
  } catch {
    // a server that never started has nothing to stop
  }
}

async function restart() {
  await stop();
  await start();
}

/** Called by VS Code when an IL, ST or XML file is opened. */
async function activate(context) {
  context.subscriptions.push(
    vscode.commands.registerCommand('ladderc.restartServer', restart),
    vscode.workspace.onDidChangeConfiguration((e) => {
      if (e.affectsConfiguration('ladderc.path')) restart();
    }),
  );
  await start();
}

function deactivate() {
  return stop();
}

module.exports = { activate, deactivate, DOCUMENT_SELECTOR, serverOptions };
