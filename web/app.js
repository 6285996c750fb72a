// Old URL of the tree page's module (pages cached before the reshape): the page is web/tree/tree_page.js.
import './tree/tree_page.js';
