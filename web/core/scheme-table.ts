/**
 * The core's scheme and host table (wasm/src/core/scheme_table.cpp), as
 * set-up writes it from the built module (scripts/setup.mjs): the page
 * knows the schemes before its worker has loaded the core, and the app, the
 * rules panel and the embed read them from here, not from a copy. A unit
 * test holds it equal to what the module answers.
 */
import table from './generated/scheme-table.json';
import type { CoreSchemeInfo } from './subdiv-core';

export const SCHEME_TABLE: CoreSchemeInfo = table;
