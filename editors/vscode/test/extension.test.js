// extension.js outside VS Code: the `vscode` module and vscode-languageclient's LanguageClient are replaced
// by recorders, so the test sees what the extension would start (command, arguments, document selector)
// and how it reacts to a setting change, a failed start and deactivation.
'use strict';

const test = require('node:test');
const assert = require('node:assert/strict');
const Module = require('node:module');
const path = require('node:path');

function harness({ ladderPath = 'ladderc', failStart = false } = {}) {
  const events = [];
  const clients = [];
  const registered = {};
  let configListener;
  const settings = { path: ladderPath };
  const vscode = {
    workspace: {
      getConfiguration: (section) => {
        assert.equal(section, 'ladderc');
        return { get: (key) => settings[key] };
      },
      createFileSystemWatcher: (glob) => ({ glob, dispose() {} }),
      onDidChangeConfiguration: (listener) => {
        configListener = listener;
        return { dispose() {} };
      },
    },
    commands: {
      registerCommand: (name, fn) => {
        registered[name] = fn;
        return { dispose() {} };
      },
    },
    window: { showErrorMessage: (msg) => events.push(['error', msg]) },
  };
  class LanguageClient {
    constructor(id, name, serverOptions, clientOptions) {
      Object.assign(this, { id, name, serverOptions, clientOptions, stopped: false });
      clients.push(this);
    }
    async start() {
      events.push(['start', this.serverOptions.command]);
      if (failStart) throw new Error('spawn ladderc ENOENT');
    }
    async stop() {
      this.stopped = true;
      events.push(['stop', this.serverOptions.command]);
    }
  }
  const file = path.join(__dirname, '..', 'extension.js');
  const load = Module._load;
  Module._load = function (request, parent, isMain) {
    if (request === 'vscode') return vscode;
    if (request === 'vscode-languageclient/node') return { LanguageClient };
    return load.call(this, request, parent, isMain);
  };
  delete require.cache[require.resolve(file)];
  let extension;
  try {
    extension = require(file);
  } finally {
    Module._load = load;
  }
  const context = { subscriptions: [] };
  return {
    extension, context, clients, events, registered, settings,
    changeConfig: (section) => configListener({ affectsConfiguration: (s) => s === section }),
  };
}

const flush = () => new Promise((resolve) => setImmediate(resolve));

test('activate starts `ladderc lsp` over stdio for IL, ST and XML files', async () => {
  const h = harness();
  await h.extension.activate(h.context);
  assert.equal(h.clients.length, 1);
  const [client] = h.clients;
  assert.equal(client.id, 'ladderc');
  assert.equal(client.serverOptions.command, 'ladderc');
  assert.deepEqual(client.serverOptions.args, ['lsp']);
  // no transport given: vscode-languageclient talks to a command over its stdin and stdout
  assert.equal(client.serverOptions.transport, undefined);
  const selector = client.clientOptions.documentSelector;
  assert.ok(selector.some((s) => s.language === 'iec-il' && s.scheme === 'file'));
  assert.ok(selector.some((s) => s.language === 'iec-st' && s.scheme === 'file'));
  assert.ok(selector.some((s) => s.pattern === '**/*.xml'));
  const watched = client.clientOptions.synchronize.fileEvents.map((w) => w.glob);
  assert.ok(watched.includes('**/*.axes.json'));
  assert.deepEqual(h.events, [['start', 'ladderc']]);
  assert.ok(h.context.subscriptions.length >= 2, 'command and listener are disposed with the extension');
  await h.extension.deactivate();
  assert.ok(client.stopped);
});

test('ladderc.path chooses the executable; a change restarts the server', async () => {
  const h = harness({ ladderPath: '  /opt/ladderc/bin/ladderc ' });
  await h.extension.activate(h.context);
  assert.equal(h.clients[0].serverOptions.command, '/opt/ladderc/bin/ladderc');
  h.settings.path = '/usr/local/bin/ladderc';
  h.changeConfig('editor.fontSize');
  await flush();
  assert.equal(h.clients.length, 1, 'an unrelated setting does not restart');
  h.changeConfig('ladderc.path');
  await flush();
  assert.equal(h.clients.length, 2);
  assert.ok(h.clients[0].stopped);
  assert.equal(h.clients[1].serverOptions.command, '/usr/local/bin/ladderc');
  assert.deepEqual(h.events.slice(1), [['stop', '/opt/ladderc/bin/ladderc'], ['start', '/usr/local/bin/ladderc']]);
  await h.extension.deactivate();
});

test('an empty ladderc.path falls back to `ladderc`; the restart command starts a new server', async () => {
  const h = harness({ ladderPath: '' });
  await h.extension.activate(h.context);
  assert.equal(h.clients[0].serverOptions.command, 'ladderc');
  await h.registered['ladderc.restartServer']();
  assert.equal(h.clients.length, 2);
  assert.ok(h.clients[0].stopped);
  assert.ok(!h.clients[1].stopped);
  await h.extension.deactivate();
  assert.ok(h.clients[1].stopped);
});

test('a server that cannot start gives one error message naming the command and the setting', async () => {
  const h = harness({ failStart: true });
  await h.extension.activate(h.context);
  const errors = h.events.filter(([kind]) => kind === 'error');
  assert.equal(errors.length, 1);
  assert.match(errors[0][1], /`ladderc lsp`/);
  assert.match(errors[0][1], /ENOENT/);
  assert.match(errors[0][1], /ladderc\.path/);
  await h.extension.deactivate();
});
