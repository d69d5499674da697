/**
 * What the Share and Embed… buttons do: Share copies the link of the current
 * state (or shows it when the clipboard refuses), Embed… opens the dialog
 * with an element and an iframe snippet. A model opened from the user's
 * computer has no URL, so both say plainly that a link cannot load it.
 */
import type { EmbedContent, EmbedDialog } from '../ui/embed-dialog';
import type { SharePanel } from '../ui/share-panel';
import type { SubdivViewer } from '../viewer/subdiv-viewer';
import type { ViewerParams } from '../viewer/viewer-params';
import { elementSnippet, iframeSnippet, shareLink } from './embed-snippets';

/** Where the shown model came from. */
export type ModelSource = { kind: 'url'; src: string } | { kind: 'file'; name: string };

export interface ShareHost {
  readonly viewer: SubdivViewer;
  modelSource(): ModelSource | null;
  /** The state as link parameters. */
  params(): ViewerParams;
}

/** Said by Share and Embed… for a model that has no URL. */
export function localFileRefusal(name: string): string {
  return (
    `${name} was opened from your computer, so a link cannot load it; ` +
    'pick a sample or load it from a URL with ?src=.'
  );
}

/** Said with every link of the custom scheme: rule sets do not fit in a link. */
export const CUSTOM_RULES_NOTE =
  'Custom rules are not carried by links: the link opens the Custom rules scheme with its first preset (Catmull-Clark), not your weights.';

export class ShareActions {
  constructor(
    private readonly host: ShareHost,
    private readonly panel: SharePanel,
    private readonly dialog: EmbedDialog,
  ) {}

  /** The link of the current state, or why there is none. */
  link(): { link: string } | { refusal: string } {
    const refusal = this.refusal();
    if (refusal) return { refusal };
    return { link: shareLink(window.location.href, this.host.params()) };
  }

  async share(): Promise<void> {
    const result = this.link();
    if ('refusal' in result) {
      this.panel.say(result.refusal);
      return;
    }
    const custom = this.host.viewer.state.scheme === 'custom' ? ` ${CUSTOM_RULES_NOTE}` : '';
    try {
      await navigator.clipboard.writeText(result.link);
      this.panel.say(`Link copied.${custom}`, custom === '');
    } catch {
      this.panel.showLink(result.link, `The clipboard was refused: copy the link from this field.${custom}`);
    }
  }

  /** What the Embed dialog shows for the current state. */
  embedContent(): EmbedContent {
    const refusal = this.refusal();
    if (refusal) return { refusal };
    const state = this.host.viewer.state;
    const params = this.host.params();
    const subject = {
      appBase: new URL('.', document.baseURI).href,
      modelName: state.modelName ?? 'model',
      faces: state.facts?.faces ?? 0,
    };
    return {
      snippets: [
        {
          id: 'element',
          title: 'Element',
          hint: 'the page loads SubdivLab’s script; sizes with your CSS',
          code: elementSnippet(params, subject),
        },
        {
          id: 'iframe',
          title: 'Iframe',
          hint: 'works where scripts are not allowed (many site builders)',
          code: iframeSnippet(params, subject),
        },
      ],
      notes: state.scheme === 'custom' ? [CUSTOM_RULES_NOTE] : [],
    };
  }

  embed(): void {
    this.panel.clear();
    this.dialog.show(this.embedContent(), this.panel.embedButton);
  }

  private refusal(): string | null {
    const source = this.host.modelSource();
    if (!source) return 'Open a sample or load a mesh from a URL first: there is no model to link to.';
    if (source.kind === 'file') return localFileRefusal(source.name);
    return null;
  }
}
