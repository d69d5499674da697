/** Entry point of the SubdivLab page: builds the app shell, exposes the test API, applies the URL's state. */
import { AppShell } from './app/app-shell';
import './ui/app.css';

const root = document.getElementById('app');
if (!root) throw new Error('index.html has no #app element');
const app = new AppShell(root);
window.__subdivlab = app.testApi();
void app.start();
