"""The ``initialize`` answer of ``aidl lsp`` (capabilities and server info), generated
from the pygls server by ``python editors/gen_lsp_capabilities.py``: do not edit.
:mod:`.boot` sends it before pygls is loaded; tests/test_lsp_features.py keeps it
equal to what pygls computes."""

CAPABILITIES = {'codeActionProvider': {'codeActionKinds': ['quickfix']},
 'codeLensProvider': {'resolveProvider': False},
 'completionProvider': {'triggerCharacters': ['.']},
 'definitionProvider': True,
 'documentFormattingProvider': True,
 'documentHighlightProvider': True,
 'documentLinkProvider': {'resolveProvider': False},
 'documentSymbolProvider': True,
 'executeCommandProvider': {'commands': []},
 'foldingRangeProvider': True,
 'hoverProvider': True,
 'inlayHintProvider': {'resolveProvider': False},
 'positionEncoding': 'utf-16',
 'referencesProvider': True,
 'renameProvider': {'prepareProvider': True},
 'semanticTokensProvider': {'full': True,
                            'legend': {'tokenModifiers': ['declaration',
                                                          'readonly',
                                                          'defaultLibrary',
                                                          'unit'],
                                       'tokenTypes': ['namespace',
                                                      'struct',
                                                      'class',
                                                      'function',
                                                      'macro',
                                                      'parameter',
                                                      'variable',
                                                      'property',
                                                      'keyword',
                                                      'comment',
                                                      'string',
                                                      'number']}},
 'signatureHelpProvider': {'retriggerCharacters': ['='], 'triggerCharacters': ['(', ',']},
 'textDocumentSync': {'change': 2, 'openClose': True, 'save': True},
 'workspace': {'fileOperations': {},
               'workspaceFolders': {'changeNotifications': True, 'supported': True}},
 'workspaceSymbolProvider': {'resolveProvider': False}}

SERVER_INFO = {'name': 'aidl', 'version': '0.2.0'}
