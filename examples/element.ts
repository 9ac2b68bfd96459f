// The <fft-ocean> example page: registering the element is all it takes (as a user would with
// `import 'three-fft-ocean/register'`).
import '../src/embed/register';
