<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="zh_CN">
<context>
    <name>AnimationBar</name>
    <message>
        <source>Step back</source>
        <translation>后退一步</translation>
    </message>
    <message>
        <source>One crank-angle step back</source>
        <translation>后退一个曲柄转角步长</translation>
    </message>
    <message>
        <source>Step forward</source>
        <translation>前进一步</translation>
    </message>
    <message>
        <source>One crank-angle step forward</source>
        <translation>前进一个曲柄转角步长</translation>
    </message>
    <message>
        <source>Crank angle φ, 0…360°: drag to scrub</source>
        <translation>曲柄转角 φ，0…360°：拖动以定位</translation>
    </message>
    <message>
        <source>Loop</source>
        <translation>循环</translation>
    </message>
    <message>
        <source>Repeat the cycle; when off, playback stops at 360°</source>
        <translation>循环播放；关闭时播放到 360° 停止</translation>
    </message>
    <message>
        <source>Speed</source>
        <translation>速度</translation>
    </message>
    <message>
        <source>Playback speed relative to real time at the first crank speed</source>
        <translation>相对于第一个曲柄转速下实际时间的播放速度</translation>
    </message>
    <message>
        <source>{0:g}×</source>
        <translation>{0:g}×</translation>
    </message>
    <message>
        <source>Crank φ (°)</source>
        <translation>曲柄 φ (°)</translation>
    </message>
    <message>
        <source>Lever ψ (°)</source>
        <translation>导杆 ψ (°)</translation>
    </message>
    <message>
        <source>Ram x (mm)</source>
        <translation>滑枕 x (mm)</translation>
    </message>
    <message>
        <source>Time t (s)</source>
        <translation>时间 t (s)</translation>
    </message>
    <message>
        <source>Ram v (m/s)</source>
        <translation>滑枕 v (m/s)</translation>
    </message>
    <message>
        <source>Ram a (m/s²)</source>
        <translation>滑枕 a (m/s²)</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation>暂停</translation>
    </message>
    <message>
        <source>Play</source>
        <translation>播放</translation>
    </message>
    <message>
        <source>Pause the animation</source>
        <translation>暂停动画</translation>
    </message>
    <message>
        <source>Play the crank cycle</source>
        <translation>播放曲柄运动循环</translation>
    </message>
    <message>
        <source>{0:g} r/min</source>
        <translation>{0:g} r/min</translation>
    </message>
</context>
<context>
    <name>DesignForm</name>
    <message>
        <source>Input</source>
        <translation>输入方式</translation>
    </message>
    <message>
        <source>Synthesis from L1, K, H</source>
        <translation>由 L1、K、H 综合</translation>
    </message>
    <message>
        <source>Direct dimensions</source>
        <translation>直接输入尺寸</translation>
    </message>
    <message>
        <source>Main dimensions</source>
        <translation>主要尺寸</translation>
    </message>
    <message>
        <source>Mechanism</source>
        <translation>机构</translation>
    </message>
    <message>
        <source>Crank speeds</source>
        <translation>曲柄转速</translation>
    </message>
    <message>
        <source>Crank length L1</source>
        <translation>曲柄长度 L1</translation>
    </message>
    <message>
        <source>Length of the crank O2A, mm</source>
        <translation>曲柄 O2A 的长度，mm</translation>
    </message>
    <message>
        <source>Time ratio K</source>
        <translation>行程速比系数 K</translation>
    </message>
    <message>
        <source>Working time / return time; greater than 1</source>
        <translation>工作行程时间 / 回程时间；须大于 1</translation>
    </message>
    <message>
        <source>Stroke H</source>
        <translation>行程 H</translation>
    </message>
    <message>
        <source>Ram (tool) stroke, mm</source>
        <translation>滑枕（刨刀）行程，mm</translation>
    </message>
    <message>
        <source>Frame distance L2</source>
        <translation>机架长度 L2</translation>
    </message>
    <message>
        <source>Distance O2O4 between crank centre and lever pivot, mm</source>
        <translation>曲柄回转中心与导杆摆动中心的距离 O2O4，mm</translation>
    </message>
    <message>
        <source>Lever length L3</source>
        <translation>导杆长度 L3</translation>
    </message>
    <message>
        <source>Length of the slotted lever O4B, mm</source>
        <translation>导杆 O4B 的长度，mm</translation>
    </message>
    <message>
        <source>Ram drive</source>
        <translation>滑枕驱动方式</translation>
    </message>
    <message>
        <source>How the lever tip drives the ram</source>
        <translation>导杆端部驱动滑枕的方式</translation>
    </message>
    <message>
        <source>Ram guide</source>
        <translation>滑枕导路</translation>
    </message>
    <message>
        <source>Where the ram guide line lies</source>
        <translation>滑枕导路线的位置</translation>
    </message>
    <message>
        <source>Guide height</source>
        <translation>导路高度</translation>
    </message>
    <message>
        <source>Height of the ram guide line above the lever pivot O4, mm</source>
        <translation>滑枕导路线距导杆摆动中心 O4 的高度，mm</translation>
    </message>
    <message>
        <source>Rod given as</source>
        <translation>连杆给定方式</translation>
    </message>
    <message>
        <source>Give the rod as a length or as L4/L3</source>
        <translation>以长度或 L4/L3 比值给出连杆</translation>
    </message>
    <message>
        <source>Rod length L4</source>
        <translation>连杆长度 L4</translation>
    </message>
    <message>
        <source>Length of the connecting rod BC, mm</source>
        <translation>连杆 BC 的长度，mm</translation>
    </message>
    <message>
        <source>Rod ratio L4/L3</source>
        <translation>连杆比 L4/L3</translation>
    </message>
    <message>
        <source>Rod length as a fraction of the lever</source>
        <translation>连杆长度与导杆长度之比</translation>
    </message>
    <message>
        <source>Rod side</source>
        <translation>连杆位置</translation>
    </message>
    <message>
        <source>Ram joint C behind (trailing) or ahead of (leading) the lever tip while cutting</source>
        <translation>切削时滑枕铰点 C 位于导杆端部之后（后置）或之前（前置）</translation>
    </message>
    <message>
        <source>Speeds, r/min</source>
        <translation>转速，r/min</translation>
    </message>
    <message>
        <source>Crank speeds in r/min; double-click to edit, + and − to add or remove</source>
        <translation>曲柄转速 (r/min)；双击编辑，用 + 和 − 添加或删除</translation>
    </message>
    <message>
        <source>Angle step</source>
        <translation>角度步长</translation>
    </message>
    <message>
        <source>Crank-angle step of the curves and the CSV export, degrees</source>
        <translation>曲线和 CSV 导出的曲柄转角步长，度</translation>
    </message>
    <message>
        <source>Block in ram slot</source>
        <translation>滑块在滑枕导槽中</translation>
    </message>
    <message>
        <source>Connecting rod</source>
        <translation>连杆</translation>
    </message>
    <message>
        <source>Through the tip's extreme positions (chord)</source>
        <translation>通过导杆端部两极限位置（弦线）</translation>
    </message>
    <message>
        <source>Mid-sagitta of the tip's arc</source>
        <translation>导杆端部圆弧矢高的中点</translation>
    </message>
    <message>
        <source>Explicit height</source>
        <translation>指定高度</translation>
    </message>
    <message>
        <source>Ratio L4/L3</source>
        <translation>比值 L4/L3</translation>
    </message>
    <message>
        <source>Length</source>
        <translation>长度</translation>
    </message>
    <message>
        <source>Trailing the tip</source>
        <translation>连杆在导杆端部后方</translation>
    </message>
    <message>
        <source>Leading the tip</source>
        <translation>连杆在导杆端部前方</translation>
    </message>
    <message>
        <source>Add a crank speed</source>
        <translation>添加一个曲柄转速</translation>
    </message>
    <message>
        <source>Remove the selected crank speed</source>
        <translation>删除选中的曲柄转速</translation>
    </message>
    <message>
        <source>The last valid design stays on screen.</source>
        <translation>屏幕上保留最后一个有效设计。</translation>
    </message>
</context>
<context>
    <name>Document</name>
    <message>
        <source>Could not open the design: %1</source>
        <translation>无法打开设计：%1</translation>
    </message>
    <message>
        <source>Could not save %1: %2</source>
        <translation>无法保存 %1：%2</translation>
    </message>
    <message>
        <source>Could not write %1: %2</source>
        <translation>无法写入 %1：%2</translation>
    </message>
    <message>
        <source>Shaper designs (*.shaper.json *.json);;All files (*)</source>
        <translation>牛头刨床设计 (*.shaper.json *.json);;所有文件 (*)</translation>
    </message>
    <message>
        <source>Unsaved changes</source>
        <translation>未保存的修改</translation>
    </message>
    <message>
        <source>The design has unsaved changes. Save them first?</source>
        <translation>设计有未保存的修改。是否先保存？</translation>
    </message>
    <message>
        <source>Open design</source>
        <translation>打开设计</translation>
    </message>
    <message>
        <source>Save design as</source>
        <translation>设计另存为</translation>
    </message>
    <message>
        <source>Export curves to CSV</source>
        <translation>导出运动曲线为 CSV</translation>
    </message>
    <message>
        <source>Export forces to CSV</source>
        <translation>导出力分析为 CSV</translation>
    </message>
    <message>
        <source>CSV files (*.csv)</source>
        <translation>CSV 文件 (*.csv)</translation>
    </message>
</context>
<context>
    <name>ExploreView</name>
    <message>
        <source>Max pressure angle (°)</source>
        <translation>最大压力角 (°)</translation>
    </message>
    <message>
        <source>Max |acceleration|, fastest speed (m/s²)</source>
        <translation>最大加速度 |a|，最高转速 (m/s²)</translation>
    </message>
    <message>
        <source>Max cutting speed, fastest speed (m/s)</source>
        <translation>最大切削速度，最高转速 (m/s)</translation>
    </message>
    <message>
        <source>Max return speed, fastest speed (m/s)</source>
        <translation>最大回程速度，最高转速 (m/s)</translation>
    </message>
    <message>
        <source>Peak crank torque, worst speed (N·m)</source>
        <translation>曲柄最大驱动力矩，最不利转速 (N·m)</translation>
    </message>
    <message>
        <source>Flywheel J_F, slowest speed (kg·m²)</source>
        <translation>飞轮转动惯量 J_F，最低转速 (kg·m²)</translation>
    </message>
    <message>
        <source>Crank L1 (mm)</source>
        <translation>曲柄 L1 (mm)</translation>
    </message>
    <message>
        <source>Time ratio K</source>
        <translation>行程速比系数 K</translation>
    </message>
    <message>
        <source>Stroke H (mm)</source>
        <translation>行程 H (mm)</translation>
    </message>
    <message>
        <source>Frame L2 (mm)</source>
        <translation>机架 L2 (mm)</translation>
    </message>
    <message>
        <source>Lever L3 (mm)</source>
        <translation>导杆 L3 (mm)</translation>
    </message>
    <message>
        <source>Guide above O4 (mm)</source>
        <translation>导路距 O4 高度 (mm)</translation>
    </message>
    <message>
        <source>Rod ratio L4/L3</source>
        <translation>连杆比 L4/L3</translation>
    </message>
    <message>
        <source>Rod L4 (mm)</source>
        <translation>连杆 L4 (mm)</translation>
    </message>
    <message>
        <source>Figure</source>
        <translation>指标</translation>
    </message>
    <message>
        <source>Across</source>
        <translation>横轴</translation>
    </message>
    <message>
        <source>Up</source>
        <translation>纵轴</translation>
    </message>
    <message>
        <source>Points per axis</source>
        <translation>每轴点数</translation>
    </message>
    <message>
        <source>Objective</source>
        <translation>优化目标</translation>
    </message>
    <message>
        <source>Compute map</source>
        <translation>计算分布图</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>取消</translation>
    </message>
    <message>
        <source>Optimize</source>
        <translation>优化</translation>
    </message>
    <message>
        <source>Optimize over the map's ranges</source>
        <translation>在分布图范围内优化</translation>
    </message>
    <message>
        <source>vary across</source>
        <translation>优化横轴参数</translation>
    </message>
    <message>
        <source>vary up</source>
        <translation>优化纵轴参数</translation>
    </message>
    <message>
        <source>Choose two different parameters.</source>
        <translation>请选择两个不同的参数。</translation>
    </message>
    <message>
        <source>Computing %1 designs…</source>
        <translation>正在计算 %1 个设计…</translation>
    </message>
    <message>
        <source>Best: %1 %2 at %3 (the design before: %4); loaded into the form.</source>
        <translation>最优值：%1 %2，位于 %3（原设计：%4）；已载入表单。</translation>
    </message>
    <message>
        <source>not enough memory</source>
        <translation>内存不足</translation>
    </message>
    <message>
        <source>%1 of %2 designs are valid.</source>
        <translation>%2 个设计中有 %1 个有效。</translation>
    </message>
    <message>
        <source>%1 — invalid: %2</source>
        <translation>%1 — 无效：%2</translation>
    </message>
    <message>
        <source>Choose one or two different free parameters.</source>
        <translation>请选择一个或两个不同的优化参数。</translation>
    </message>
    <message>
        <source>Optimizing…</source>
        <translation>正在优化…</translation>
    </message>
    <message>
        <source>Could not compute: %1</source>
        <translation>无法计算：%1</translation>
    </message>
    <message>
        <source>Cancelled.</source>
        <translation>已取消。</translation>
    </message>
    <message>
        <source>the image could not be written</source>
        <translation>无法写入图像</translation>
    </message>
</context>
<context>
    <name>ForcesPanel</name>
    <message>
        <source>Shaper forces and torque</source>
        <translation>牛头刨床受力与力矩</translation>
    </message>
    <message>
        <source>Mass m3</source>
        <translation>质量 m3</translation>
    </message>
    <message>
        <source>Mass of the slotted lever O4B, kg</source>
        <translation>导杆 O4B 的质量，kg</translation>
    </message>
    <message>
        <source>Centre of mass c</source>
        <translation>质心位置 c</translation>
    </message>
    <message>
        <source>Distance of the lever's centre of mass from O4 along O4B, mm; leave empty for L3/2</source>
        <translation>导杆质心沿 O4B 距 O4 的距离，mm；留空则取 L3/2</translation>
    </message>
    <message>
        <source>Inertia J3</source>
        <translation>转动惯量 J3</translation>
    </message>
    <message>
        <source>Moment of inertia of the lever about its centre of mass, kg·m²</source>
        <translation>导杆绕其质心的转动惯量，kg·m²</translation>
    </message>
    <message>
        <source>Mass m5</source>
        <translation>质量 m5</translation>
    </message>
    <message>
        <source>Mass of the ram with the tool, kg</source>
        <translation>滑枕（含刨刀）的质量，kg</translation>
    </message>
    <message>
        <source>Centre of mass dx</source>
        <translation>质心偏移 dx</translation>
    </message>
    <message>
        <source>Horizontal offset of the ram's centre of mass from the ram joint C, mm (+ in the cutting direction)</source>
        <translation>滑枕质心相对铰点 C 的水平偏移，mm（切削方向为正）</translation>
    </message>
    <message>
        <source>Centre of mass dy</source>
        <translation>质心偏移 dy</translation>
    </message>
    <message>
        <source>Vertical offset of the ram's centre of mass from the ram joint C, mm (+ up)</source>
        <translation>滑枕质心相对铰点 C 的竖直偏移，mm（向上为正）</translation>
    </message>
    <message>
        <source>Rod mass m4</source>
        <translation>连杆质量 m4</translation>
    </message>
    <message>
        <source>Mass of the connecting rod BC, a uniform bar, kg (rod variant only)</source>
        <translation>连杆 BC 的质量（按均质杆计），kg（仅连杆方案）</translation>
    </message>
    <message>
        <source>Block mass</source>
        <translation>滑块质量</translation>
    </message>
    <message>
        <source>Mass of the sliding block at the crank pin A, kg</source>
        <translation>曲柄销 A 处滑块的质量，kg</translation>
    </message>
    <message>
        <source>Cutting force P</source>
        <translation>切削阻力 P</translation>
    </message>
    <message>
        <source>Cutting resistance on the tool, against the cut, N</source>
        <translation>作用于刨刀、与切削方向相反的切削阻力，N</translation>
    </message>
    <message>
        <source>Tool below guide yP</source>
        <translation>刀尖距导路 yP</translation>
    </message>
    <message>
        <source>Height of the tool point below the ram guide line, mm (negative = above)</source>
        <translation>刀尖在滑枕导路线以下的距离，mm（负值表示在其上方）</translation>
    </message>
    <message>
        <source>Idle margin</source>
        <translation>空刀距离</translation>
    </message>
    <message>
        <source>Uncut run-in and run-out at each end of the working stroke, % of the stroke H (0 to under 50)</source>
        <translation>工作行程两端的空刀距离，占行程 H 的百分比（0 至小于 50）</translation>
    </message>
    <message>
        <source>Gravity</source>
        <translation>重力</translation>
    </message>
    <message>
        <source>Include the weights of the links (g = 9.81 m/s²)</source>
        <translation>计入各构件重力（g = 9.81 m/s²）</translation>
    </message>
    <message>
        <source>Speed fluctuation δ</source>
        <translation>速度波动系数 δ</translation>
    </message>
    <message>
        <source>Coefficient of speed fluctuation (ωmax − ωmin)/ωmean the flywheel must hold, between 0 and 1; a fraction such as 1/30 is accepted</source>
        <translation>飞轮须保证的速度波动系数 (ωmax − ωmin)/ωm，介于 0 与 1 之间；可输入分数，如 1/30</translation>
    </message>
    <message>
        <source>Crank driving torque</source>
        <translation>曲柄驱动力矩</translation>
    </message>
    <message>
        <source>Input power</source>
        <translation>输入功率</translation>
    </message>
    <message>
        <source>Cumulative excess energy ΔE</source>
        <translation>累积盈亏功 ΔE</translation>
    </message>
    <message>
        <source>Joint force magnitudes</source>
        <translation>运动副反力大小</translation>
    </message>
    <message>
        <source>Crank torque</source>
        <translation>驱动力矩</translation>
    </message>
    <message>
        <source>Energy ΔE</source>
        <translation>盈亏功 ΔE</translation>
    </message>
    <message>
        <source>Joint force |F|</source>
        <translation>运动副反力 |F|</translation>
    </message>
    <message>
        <source>O₂ crank bearing</source>
        <translation>O₂ 曲柄轴承</translation>
    </message>
    <message>
        <source>A block on lever</source>
        <translation>A 滑块对导杆</translation>
    </message>
    <message>
        <source>O₄ lever pivot</source>
        <translation>O₄ 导杆支座</translation>
    </message>
    <message>
        <source>B lever tip</source>
        <translation>B 导杆端部</translation>
    </message>
    <message>
        <source>C rod on ram</source>
        <translation>C 连杆对滑枕</translation>
    </message>
    <message>
        <source>Guide normal force</source>
        <translation>导路法向反力</translation>
    </message>
    <message>
        <source>guide</source>
        <translation>导路</translation>
    </message>
    <message>
        <source>{0} r/min</source>
        <translation>{0} r/min</translation>
    </message>
    <message>
        <source>Slotted lever</source>
        <translation>导杆</translation>
    </message>
    <message>
        <source>Ram and tool</source>
        <translation>滑枕与刨刀</translation>
    </message>
    <message>
        <source>Rod and block</source>
        <translation>连杆与滑块</translation>
    </message>
    <message>
        <source>Cutting</source>
        <translation>切削</translation>
    </message>
    <message>
        <source>Flywheel</source>
        <translation>飞轮</translation>
    </message>
    <message>
        <source>include weights</source>
        <translation>计入重力</translation>
    </message>
    <message>
        <source>Joint forces at:</source>
        <translation>运动副反力转速：</translation>
    </message>
    <message>
        <source>Crank speed whose joint forces are plotted</source>
        <translation>绘制运动副反力所用的曲柄转速</translation>
    </message>
    <message>
        <source>Values under the mouse; click a plot to move the mechanism to that crank position</source>
        <translation>鼠标处的数值；单击曲线使机构转到该曲柄位置</translation>
    </message>
    <message>
        <source>Point at a plot to read values; click to set the crank angle</source>
        <translation>指向曲线读取数值；单击设置曲柄转角</translation>
    </message>
    <message>
        <source>Crank angle φ (°)</source>
        <translation>曲柄转角 φ (°)</translation>
    </message>
    <message>
        <source>cutting</source>
        <translation>切削区</translation>
    </message>
    <message>
        <source>L3/2 = {0}</source>
        <translation>L3/2 = {0}</translation>
    </message>
    <message>
        <source>mean torque</source>
        <translation>平均力矩</translation>
    </message>
    <message>
        <source>Joint forces at {0}</source>
        <translation>{0} 时的运动副反力</translation>
    </message>
    <message>
        <source>The last valid results stay on screen.</source>
        <translation>屏幕上保留最后一次有效结果。</translation>
    </message>
    <message>
        <source>φ = {0}°</source>
        <translation>φ = {0}°</translation>
    </message>
</context>
<context>
    <name>MainWindow</name>
    <message>
        <source>&amp;New</source>
        <translation>新建(&amp;N)</translation>
    </message>
    <message>
        <source>Start a new design from the defaults</source>
        <translation>从默认值开始新设计</translation>
    </message>
    <message>
        <source>&amp;Open…</source>
        <translation>打开(&amp;O)…</translation>
    </message>
    <message>
        <source>Open a design file</source>
        <translation>打开设计文件</translation>
    </message>
    <message>
        <source>&amp;Save</source>
        <translation>保存(&amp;S)</translation>
    </message>
    <message>
        <source>Save the design</source>
        <translation>保存设计</translation>
    </message>
    <message>
        <source>Save &amp;As…</source>
        <translation>另存为(&amp;A)…</translation>
    </message>
    <message>
        <source>Save the design under a new name</source>
        <translation>以新名称保存设计</translation>
    </message>
    <message>
        <source>Export curves to &amp;CSV…</source>
        <translation>导出运动曲线 CSV(&amp;C)…</translation>
    </message>
    <message>
        <source>All speeds, at the form's angle step</source>
        <translation>全部转速，按表单中的角度步长</translation>
    </message>
    <message>
        <source>Export &amp;forces to CSV…</source>
        <translation>导出力分析 CSV(&amp;F)…</translation>
    </message>
    <message>
        <source>Crank torque, power and joint forces, all speeds</source>
        <translation>曲柄驱动力矩、功率和运动副反力，全部转速</translation>
    </message>
    <message>
        <source>Export &amp;plots (PNG/SVG)…</source>
        <translation>导出曲线图 (PNG/SVG)(&amp;P)…</translation>
    </message>
    <message>
        <source>Save the plots of the current tab as an image</source>
        <translation>将当前页的曲线保存为图像</translation>
    </message>
    <message>
        <source>Export sc&amp;heme (PNG/SVG)…</source>
        <translation>导出机构简图 (PNG/SVG)(&amp;H)…</translation>
    </message>
    <message>
        <source>Save the mechanism drawing as an image</source>
        <translation>将机构简图保存为图像</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>退出(&amp;Q)</translation>
    </message>
    <message>
        <source>&amp;About</source>
        <translation>关于(&amp;A)</translation>
    </message>
    <message>
        <source>Kinematics</source>
        <translation>运动分析</translation>
    </message>
    <message>
        <source>Forces</source>
        <translation>力分析</translation>
    </message>
    <message>
        <source>Explore</source>
        <translation>设计空间</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>文件(&amp;F)</translation>
    </message>
    <message>
        <source>Open &amp;Recent</source>
        <translation>最近打开(&amp;R)</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>视图(&amp;V)</translation>
    </message>
    <message>
        <source>&amp;Language</source>
        <translation>语言(&amp;L)</translation>
    </message>
    <message>
        <source>&amp;Animation</source>
        <translation>动画(&amp;A)</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>帮助(&amp;H)</translation>
    </message>
    <message>
        <source>Untitled</source>
        <translation>未命名</translation>
    </message>
    <message>
        <source>K = %1, H = %2 mm, θ = %3°</source>
        <translation>K = %1，H = %2 mm，θ = %3°</translation>
    </message>
    <message>
        <source>Shaper Designer</source>
        <translation>牛头刨床机构设计</translation>
    </message>
    <message>
        <source>Saved %1</source>
        <translation>已保存 %1</translation>
    </message>
    <message>
        <source>Export image</source>
        <translation>导出图像</translation>
    </message>
    <message>
        <source>PNG image (*.png);;SVG drawing (*.svg)</source>
        <translation>PNG 图像 (*.png);;SVG 矢量图 (*.svg)</translation>
    </message>
    <message>
        <source>Could not write %1: %2</source>
        <translation>无法写入 %1：%2</translation>
    </message>
    <message>
        <source>About Shaper Designer</source>
        <translation>关于 牛头刨床机构设计</translation>
    </message>
    <message>
        <source>Shaper Designer: synthesis and kinematics of the quick-return mechanism of a shaper (crank, slotted lever, ram).
Lengths in mm, speeds in r/min.</source>
        <translation>牛头刨床机构设计：牛头刨床急回机构（曲柄、导杆、滑枕）的尺度综合与运动分析。
长度单位 mm，转速单位 r/min。</translation>
    </message>
</context>
<context>
    <name>MetricsPanel</name>
    <message>
        <source>Cycle time, s</source>
        <translation>运动周期，s</translation>
    </message>
    <message>
        <source>Working time, s</source>
        <translation>工作行程时间，s</translation>
    </message>
    <message>
        <source>Return time, s</source>
        <translation>回程时间，s</translation>
    </message>
    <message>
        <source>Max cutting speed, m/s</source>
        <translation>最大切削速度，m/s</translation>
    </message>
    <message>
        <source>Mean cutting speed, m/s</source>
        <translation>平均切削速度，m/s</translation>
    </message>
    <message>
        <source>Max return speed, m/s</source>
        <translation>最大回程速度，m/s</translation>
    </message>
    <message>
        <source>Max |acceleration|, m/s²</source>
        <translation>最大加速度（绝对值），m/s²</translation>
    </message>
    <message>
        <source>Max lever ω, rad/s</source>
        <translation>导杆最大角速度，rad/s</translation>
    </message>
    <message>
        <source>Max lever α, rad/s²</source>
        <translation>导杆最大角加速度，rad/s²</translation>
    </message>
    <message>
        <source>Mean crank torque, N·m</source>
        <translation>平均驱动力矩，N·m</translation>
    </message>
    <message>
        <source>Max crank torque, N·m</source>
        <translation>最大驱动力矩，N·m</translation>
    </message>
    <message>
        <source>Motor power (before efficiency), kW</source>
        <translation>电动机功率（未计效率），kW</translation>
    </message>
    <message>
        <source>Peak input power, kW</source>
        <translation>峰值输入功率，kW</translation>
    </message>
    <message>
        <source>Energy fluctuation ΔW_max, J</source>
        <translation>最大盈亏功 ΔW_max，J</translation>
    </message>
    <message>
        <source>Flywheel J_F on crank shaft, kg·m²</source>
        <translation>曲柄轴上飞轮转动惯量 J_F，kg·m²</translation>
    </message>
    <message>
        <source>J_F less mechanism's own, kg·m²</source>
        <translation>扣除机构自身等效惯量后的 J_F，kg·m²</translation>
    </message>
    <message>
        <source>Forces and flywheel</source>
        <translation>力与飞轮</translation>
    </message>
    <message>
        <source>Constant crank speed; loads as set in the Forces tab</source>
        <translation>曲柄匀速转动；载荷按“力分析”页设置</translation>
    </message>
    <message>
        <source>Synthesized dimensions</source>
        <translation>综合所得尺寸</translation>
    </message>
    <message>
        <source>Measured cycle</source>
        <translation>实测运动循环</translation>
    </message>
    <message>
        <source>Extreme-position angle θ</source>
        <translation>极位夹角 θ</translation>
    </message>
    <message>
        <source>Crank angle between the two limit positions; equals the lever swing</source>
        <translation>两极限位置之间的曲柄夹角；等于导杆摆角</translation>
    </message>
    <message>
        <source>Frame O2O4 L2</source>
        <translation>机架 O2O4 L2</translation>
    </message>
    <message>
        <source>Distance from crank centre to lever pivot</source>
        <translation>曲柄回转中心到导杆摆动中心的距离</translation>
    </message>
    <message>
        <source>Lever O4B L3</source>
        <translation>导杆 O4B L3</translation>
    </message>
    <message>
        <source>Length of the slotted lever</source>
        <translation>导杆长度</translation>
    </message>
    <message>
        <source>Rod BC L4</source>
        <translation>连杆 BC L4</translation>
    </message>
    <message>
        <source>Connecting-rod length (rod variant)</source>
        <translation>连杆长度（连杆方案）</translation>
    </message>
    <message>
        <source>Guide above O4</source>
        <translation>导路距 O4 高度</translation>
    </message>
    <message>
        <source>Height of the ram guide line above the lever pivot</source>
        <translation>滑枕导路线距导杆摆动中心的高度</translation>
    </message>
    <message>
        <source>Guide above O2, h</source>
        <translation>导路距 O2 高度 h</translation>
    </message>
    <message>
        <source>Height of the ram guide line above the crank centre</source>
        <translation>滑枕导路线距曲柄回转中心的高度</translation>
    </message>
    <message>
        <source>K of the dimensions</source>
        <translation>由尺寸得出的 K</translation>
    </message>
    <message>
        <source>(π + θ)/(π − θ)</source>
        <translation>(π + θ)/(π − θ)</translation>
    </message>
    <message>
        <source>H of the dimensions</source>
        <translation>由尺寸得出的行程 H</translation>
    </message>
    <message>
        <source>2·L3·sin(θ/2)</source>
        <translation>2·L3·sin(θ/2)</translation>
    </message>
    <message>
        <source>Measured K</source>
        <translation>实测 K</translation>
    </message>
    <message>
        <source>Working / return crank angle, from the ram's dead points</source>
        <translation>工作行程与回程的曲柄转角之比，由滑枕极限位置测得</translation>
    </message>
    <message>
        <source>Measured stroke</source>
        <translation>实测行程</translation>
    </message>
    <message>
        <source>Distance between the ram's dead points</source>
        <translation>滑枕两极限位置之间的距离</translation>
    </message>
    <message>
        <source>Working crank angle</source>
        <translation>工作行程曲柄转角</translation>
    </message>
    <message>
        <source>Crank rotation during the cutting stroke</source>
        <translation>工作行程中曲柄转过的角度</translation>
    </message>
    <message>
        <source>Return crank angle</source>
        <translation>回程曲柄转角</translation>
    </message>
    <message>
        <source>Crank rotation during the return stroke</source>
        <translation>回程中曲柄转过的角度</translation>
    </message>
    <message>
        <source>Max pressure angle at ram</source>
        <translation>滑枕处最大压力角</translation>
    </message>
    <message>
        <source>Largest angle between the rod and the guide</source>
        <translation>连杆与导路之间的最大夹角</translation>
    </message>
    <message>
        <source>%1 mm</source>
        <translation>%1 mm</translation>
    </message>
    <message>
        <source>%1°</source>
        <translation>%1°</translation>
    </message>
    <message>
        <source>%1 r/min</source>
        <translation>%1 r/min</translation>
    </message>
</context>
<context>
    <name>PlotsWidget</name>
    <message>
        <source>Shaper motion diagrams</source>
        <translation>牛头刨床运动线图</translation>
    </message>
    <message>
        <source>X axis:</source>
        <translation>横坐标：</translation>
    </message>
    <message>
        <source>Crank angle (°)</source>
        <translation>曲柄转角 (°)</translation>
    </message>
    <message>
        <source>Time (s)</source>
        <translation>时间 (s)</translation>
    </message>
    <message>
        <source>Plot against the crank angle (0–360°) or against time (each speed's own cycle)</source>
        <translation>以曲柄转角 (0–360°) 或时间（各转速自身的周期）为横坐标</translation>
    </message>
    <message>
        <source>Lever plots</source>
        <translation>导杆曲线</translation>
    </message>
    <message>
        <source>Show the slotted lever's angle, angular velocity or angular acceleration</source>
        <translation>显示导杆的角位移、角速度或角加速度</translation>
    </message>
    <message>
        <source>Values under the mouse; click a plot to move the mechanism to that crank position</source>
        <translation>鼠标处的数值；单击曲线使机构转到该曲柄位置</translation>
    </message>
    <message>
        <source>Crank angle φ (°)</source>
        <translation>曲柄转角 φ (°)</translation>
    </message>
    <message>
        <source>Time t (s)</source>
        <translation>时间 t (s)</translation>
    </message>
    <message>
        <source>working stroke</source>
        <translation>工作行程</translation>
    </message>
    <message>
        <source>return stroke</source>
        <translation>回程</translation>
    </message>
    <message>
        <source>Point at a plot to read values; click to set the crank angle</source>
        <translation>指向曲线读取数值；单击设置曲柄转角</translation>
    </message>
    <message>
        <source>Ram displacement</source>
        <translation>滑枕位移</translation>
    </message>
    <message>
        <source>Ram velocity</source>
        <translation>滑枕速度</translation>
    </message>
    <message>
        <source>Ram acceleration</source>
        <translation>滑枕加速度</translation>
    </message>
    <message>
        <source>Lever angle</source>
        <translation>导杆角位移</translation>
    </message>
    <message>
        <source>Lever angular velocity</source>
        <translation>导杆角速度</translation>
    </message>
    <message>
        <source>Lever angular acceleration</source>
        <translation>导杆角加速度</translation>
    </message>
    <message>
        <source>Lever angle ψ</source>
        <translation>导杆角位移 ψ</translation>
    </message>
    <message>
        <source>Lever ω</source>
        <translation>导杆 ω</translation>
    </message>
    <message>
        <source>Lever α</source>
        <translation>导杆 α</translation>
    </message>
    <message>
        <source>{0} r/min</source>
        <translation>{0} r/min</translation>
    </message>
    <message>
        <source>φ = {0}°</source>
        <translation>φ = {0}°</translation>
    </message>
    <message>
        <source>t = {0} s</source>
        <translation>t = {0} s</translation>
    </message>
</context>
<context>
    <name>SchemeWidget</name>
    <message>
        <source>Cannot export to '{0}': use .png or .svg</source>
        <translation>无法导出到“{0}”：请使用 .png 或 .svg</translation>
    </message>
    <message>
        <source>Shaper mechanism</source>
        <translation>牛头刨床机构</translation>
    </message>
    <message>
        <source>Fit</source>
        <translation>适应窗口</translation>
    </message>
    <message>
        <source>Zoom to show the whole mechanism</source>
        <translation>缩放以显示整个机构</translation>
    </message>
    <message>
        <source>Show dimensions</source>
        <translation>显示尺寸</translation>
    </message>
    <message>
        <source>Show the key dimensions L1, L2, L3, h and the stroke H</source>
        <translation>显示主要尺寸 L1、L2、L3、h 和行程 H</translation>
    </message>
    <message>
        <source>Show forces</source>
        <translation>显示受力</translation>
    </message>
    <message>
        <source>Show the joint forces at the first crank speed as arrows, to one scale</source>
        <translation>以统一比例用箭头显示第一个曲柄转速下的运动副反力</translation>
    </message>
    <message>
        <source>{0:.1f} kN</source>
        <translation>{0:.1f} kN</translation>
    </message>
    <message>
        <source>{0:.0f} N</source>
        <translation>{0:.0f} N</translation>
    </message>
    <message>
        <source>Wheel: zoom, drag: pan, right click: more</source>
        <translation>滚轮：缩放，拖动：平移，右键：更多</translation>
    </message>
    <message>
        <source>L2 = {0:.1f}</source>
        <translation>L2 = {0:.1f}</translation>
    </message>
    <message>
        <source>h = {0:.1f}</source>
        <translation>h = {0:.1f}</translation>
    </message>
    <message>
        <source>L3 = {0:.1f}</source>
        <translation>L3 = {0:.1f}</translation>
    </message>
    <message>
        <source>L1 = {0:.1f}</source>
        <translation>L1 = {0:.1f}</translation>
    </message>
    <message>
        <source>H = {0:.1f}</source>
        <translation>H = {0:.1f}</translation>
    </message>
    <message>
        <source>Forces at {0} r/min: all zero</source>
        <translation>{0} r/min 时各力均为零</translation>
    </message>
    <message>
        <source>{0:g} kN</source>
        <translation>{0:g} kN</translation>
    </message>
    <message>
        <source>{0:g} N</source>
        <translation>{0:g} N</translation>
    </message>
    <message>
        <source>Forces at {0} r/min, scale: {1:g} mm ≙ {2}</source>
        <translation>{0} r/min 时的受力，比例：{1:g} mm ≙ {2}</translation>
    </message>
</context>
<context>
    <name>app</name>
    <message>
        <source>An internal error occurred; the design on screen is unchanged. Details were written to %1.</source>
        <translation>发生内部错误；屏幕上的设计未改变。详细信息已写入 %1。</translation>
    </message>
</context>
<context>
    <name>messages</name>
    <message>
        <source>Crank length L1</source>
        <translation>曲柄长度 L1</translation>
    </message>
    <message>
        <source>Time ratio K</source>
        <translation>行程速比系数 K</translation>
    </message>
    <message>
        <source>Stroke H</source>
        <translation>行程 H</translation>
    </message>
    <message>
        <source>Frame distance L2</source>
        <translation>机架长度 L2</translation>
    </message>
    <message>
        <source>Lever length L3</source>
        <translation>导杆长度 L3</translation>
    </message>
    <message>
        <source>Ram guide</source>
        <translation>滑枕导路</translation>
    </message>
    <message>
        <source>Rod length L4</source>
        <translation>连杆长度 L4</translation>
    </message>
    <message>
        <source>Rod ratio L4/L3</source>
        <translation>连杆比 L4/L3</translation>
    </message>
    <message>
        <source>Rod side</source>
        <translation>连杆位置</translation>
    </message>
    <message>
        <source>Crank speeds</source>
        <translation>曲柄转速</translation>
    </message>
    <message>
        <source>Angle step</source>
        <translation>角度步长</translation>
    </message>
    <message>
        <source>Lever mass</source>
        <translation>导杆质量</translation>
    </message>
    <message>
        <source>Lever centre of mass</source>
        <translation>导杆质心位置</translation>
    </message>
    <message>
        <source>Lever moment of inertia</source>
        <translation>导杆转动惯量</translation>
    </message>
    <message>
        <source>Ram mass</source>
        <translation>滑枕质量</translation>
    </message>
    <message>
        <source>Ram centre-of-mass offset</source>
        <translation>滑枕质心偏移</translation>
    </message>
    <message>
        <source>Rod mass</source>
        <translation>连杆质量</translation>
    </message>
    <message>
        <source>Crank mass</source>
        <translation>曲柄质量</translation>
    </message>
    <message>
        <source>Block mass</source>
        <translation>滑块质量</translation>
    </message>
    <message>
        <source>Cutting force P</source>
        <translation>切削阻力 P</translation>
    </message>
    <message>
        <source>Tool height below guide</source>
        <translation>刀尖距导路的高度</translation>
    </message>
    <message>
        <source>Idle margin</source>
        <translation>空刀距离</translation>
    </message>
    <message>
        <source>Speed fluctuation δ</source>
        <translation>速度波动系数 δ</translation>
    </message>
    <message>
        <source>Gravity</source>
        <translation>重力</translation>
    </message>
    <message>
        <source>must be greater than %1 and at most %2 %3</source>
        <translation>须大于 %1 且不大于 %2 %3</translation>
    </message>
    <message>
        <source>must be at least %1 and at most %2 %3</source>
        <translation>须不小于 %1 且不大于 %2 %3</translation>
    </message>
    <message>
        <source>must be at least %1 and less than %2 %3</source>
        <translation>须不小于 %1 且小于 %2 %3</translation>
    </message>
    <message>
        <source>must be greater than %1 and less than %2 %3</source>
        <translation>须大于 %1 且小于 %2 %3</translation>
    </message>
    <message>
        <source>must be a pair (dx, dy) in mm</source>
        <translation>须为一对坐标 (dx, dy)，单位 mm</translation>
    </message>
    <message>
        <source>must be a number</source>
        <translation>须为数字</translation>
    </message>
    <message>
        <source>must be a finite number</source>
        <translation>须为有限数值</translation>
    </message>
    <message>
        <source>must be at least %1 mm for this crank and K, so that the crank pin stays on the lever</source>
        <translation>对此曲柄和 K 须不小于 %1 mm，以使曲柄销始终在导杆上</translation>
    </message>
    <message>
        <source>must be shorter than the frame O2O4 (%1 mm)</source>
        <translation>须短于机架 O2O4（%1 mm）</translation>
    </message>
    <message>
        <source>must be at least L2 + L1 = %1 mm, so that the crank pin stays on the lever</source>
        <translation>须不小于 L2 + L1 = %1 mm，以使曲柄销始终在导杆上</translation>
    </message>
    <message>
        <source>must be more than L2 + L1 = %1 mm above the lever pivot, so that the ram clears the crank</source>
        <translation>须高出导杆摆动中心 L2 + L1 = %1 mm 以上，使滑枕不与曲柄干涉</translation>
    </message>
    <message>
        <source>must be at most the lever length %1 mm: the block on the lever tip cannot reach a higher guide</source>
        <translation>须不大于导杆长度 %1 mm：导杆端部的滑块无法到达更高的导路</translation>
    </message>
    <message>
        <source>must be more than %1 mm to reach the guide line over the whole cycle</source>
        <translation>须大于 %1 mm，才能在整个循环中到达导路线</translation>
    </message>
    <message>
        <source>the rod passes a dead-centre position against the lever; lengthen the rod or move the guide line</source>
        <translation>连杆与导杆会经过死点位置；请加长连杆或移动导路线</translation>
    </message>
    <message>
        <source>must be at least %1 for this crank and stroke, so that the frame and the lever stay at most %2 mm</source>
        <translation>对此曲柄和行程须不小于 %1，以使机架和导杆长度不超过 %2 mm</translation>
    </message>
    <message>
        <source>must be at most %1 mm (0.866·L2), so that the time ratio K stays at most %2</source>
        <translation>须不大于 %1 mm（0.866·L2），以使行程速比系数 K 不超过 %2</translation>
    </message>
    <message>
        <source>give 1 to %1 crank speeds</source>
        <translation>请给出 1 到 %1 个曲柄转速</translation>
    </message>
    <message>
        <source>gives more than %1 angles; use a larger step</source>
        <translation>角度数超过 %1；请使用更大的步长</translation>
    </message>
    <message>
        <source>must be given either as a length or as a ratio L4/L3, not both</source>
        <translation>只能以长度或比值 L4/L3 之一给出，不能同时给出</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
</context>
</TS>
