import { createServer } from 'vite';
import FFT from 'fft.js';
const server = await createServer({ server: { middlewareMode: true }, appType: 'custom', logLevel: 'silent', optimizeDeps:{noDiscovery:true} });
const { BatchedInverseFft2D } = await server.ssrLoadModule('/src/sim/fft.ts');
function median(a){a.sort((x,y)=>x-y);return a[a.length>>1];}
for (const n of [256,512]) {
  for (const F of [1,4]) {
    const fft = new BatchedInverseFft2D(n, F);
    const src = new Float32Array(fft.inputReal.length); for(let i=0;i<src.length;i++)src[i]=Math.random();
    const t=[]; for(let r=0;r<60;r++){fft.inputReal.set(src);fft.inputImag.set(src);const s=performance.now(); fft.run(); t.push(performance.now()-s);}
    console.log(JSON.stringify({n,F,ms:median(t).toFixed(3)}));
  }
  const f = new FFT(n); const inp = f.createComplexArray(); const out=f.createComplexArray(); const data = new Float64Array(2*n*n); const col=f.createComplexArray(); const colOut=f.createComplexArray();
  const t=[]; for(let r=0;r<60;r++){for(let i=0;i<data.length;i++)data[i]=Math.random();const s=performance.now();
    for(let row=0;row<n;row++){ for(let i=0;i<2*n;i++)inp[i]=data[row*2*n+i]; f.inverseTransform(out,inp); for(let i=0;i<2*n;i++)data[row*2*n+i]=out[i]; }
    for(let c=0;c<n;c++){ for(let r2=0;r2<n;r2++){col[2*r2]=data[r2*2*n+2*c];col[2*r2+1]=data[r2*2*n+2*c+1];} f.inverseTransform(colOut,col); for(let r2=0;r2<n;r2++){data[r2*2*n+2*c]=colOut[2*r2];data[r2*2*n+2*c+1]=colOut[2*r2+1];} }
    t.push(performance.now()-s);}
  console.log(JSON.stringify({n,path:'fft.js',ms:median(t).toFixed(3)}));
}
await server.close();
