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
    <name>CadFontChoice</name>
    <message>
        <source>DXF drawing, texts in the GB style for AutoCAD and ZWCAD (*.dxf)</source>
        <translation>DXF 图形，文字为 GB 样式，供 AutoCAD 和中望CAD 使用 (*.dxf)</translation>
    </message>
    <message>
        <source>DXF drawing, texts as outlines for every CAD program, LibreCAD too (*.dxf)</source>
        <translation>DXF 图形，文字为轮廓，供所有 CAD 软件（含 LibreCAD）使用 (*.dxf)</translation>
    </message>
    <message>
        <source>GB style (AutoCAD, ZWCAD; editable)</source>
        <translation>GB 样式（AutoCAD、中望CAD；可编辑）</translation>
    </message>
    <message>
        <source>Outlines (every CAD program, LibreCAD too)</source>
        <translation>轮廓（所有 CAD 软件，含 LibreCAD）</translation>
    </message>
    <message>
        <source>How a DXF writes its texts. GB style: text in the GB fonts (gbenor.shx, gbcbig.shx), editable in AutoCAD and ZWCAD, which have them; LibreCAD draws its Chinese and Greek in its font wqy-unicode, which its Windows and macOS builds have and Debian's and Ubuntu's lack (there, Chinese as dots, no Greek letters). Outlines: each character as a filled outline, drawn alike by every CAD program, LibreCAD included, but no longer editable as text; they need a font with Chinese characters (fonts-noto-cjk).</source>
        <translation>DXF 中文字的写法。GB 样式：以国标字体（gbenor.shx、gbcbig.shx）书写的文字，在装有这些字体的 AutoCAD 和中望CAD 中可编辑；LibreCAD 用其 wqy-unicode 字体画其中的汉字和希腊字母，其 Windows 和 macOS 版带有该字体，Debian 和 Ubuntu 版没有（在那里汉字画成圆点，希腊字母漏掉）。轮廓：每个字符画成填充的轮廓，所有 CAD 软件（包括 LibreCAD）显示一致，但不能再作为文字编辑；需要一种含中文字形的字体（fonts-noto-cjk）。</translation>
    </message>
    <message>
        <source>No font with Chinese characters is installed for the outlines: install one (on Debian/Ubuntu: fonts-noto-cjk) or choose the GB style.</source>
        <translation>未安装可用于轮廓的含中文字形的字体：请安装一个（Debian/Ubuntu 上为 fonts-noto-cjk），或选择 GB 样式。</translation>
    </message>
</context>
<context>
    <name>CamForm</name>
    <message>
        <source>Arm l</source>
        <translation>摆臂长 l</translation>
    </message>
    <message>
        <source>Swing ψmax</source>
        <translation>最大摆角 ψmax</translation>
    </message>
    <message>
        <source>Rise</source>
        <translation>推程运动角</translation>
    </message>
    <message>
        <source>Outer dwell</source>
        <translation>远休止角</translation>
    </message>
    <message>
        <source>Return</source>
        <translation>回程运动角</translation>
    </message>
    <message>
        <source>Rise law</source>
        <translation>推程运动规律</translation>
    </message>
    <message>
        <source>Return law</source>
        <translation>回程运动规律</translation>
    </message>
    <message>
        <source>[α] rise</source>
        <translation>推程许用压力角 [α]</translation>
    </message>
    <message>
        <source>[α] return</source>
        <translation>回程许用压力角</translation>
    </message>
    <message>
        <source>Roller r</source>
        <translation>滚子半径 r</translation>
    </message>
    <message>
        <source>Check base r0</source>
        <translation>校核基圆半径 r0</translation>
    </message>
    <message>
        <source>Check distance a</source>
        <translation>校核中心距 a</translation>
    </message>
    <message>
        <source>Rise at crank φ</source>
        <translation>推程起点曲柄转角 φ</translation>
    </message>
    <message>
        <source>Hub radius</source>
        <translation>轮毂半径</translation>
    </message>
    <message>
        <source>Pivot boss radius</source>
        <translation>摆动中心凸台半径</translation>
    </message>
    <message>
        <source>Least clearance</source>
        <translation>最小间隙</translation>
    </message>
    <message>
        <source>Allowed pressure angle on the return, °. The default %1° is said in the textbooks: the follower returns unloaded, closed by its spring, so the return may take 70°–80° against 30°–45° on the working rise.</source>
        <translation>回程许用压力角，°。默认 %1° 取自教材：从动件回程不受工作载荷，靠弹簧锁合返回，故回程可取 70°–80°，而工作推程取 30°–45°。</translation>
    </message>
    <message>
        <source>parabolic</source>
        <translation>等加速等减速</translation>
    </message>
    <message>
        <source>cosine</source>
        <translation>余弦加速度</translation>
    </message>
    <message>
        <source>sine (cycloidal)</source>
        <translation>正弦加速度（摆线）</translation>
    </message>
    <message>
        <source>3-4-5 polynomial</source>
        <translation>3-4-5 多项式</translation>
    </message>
    <message>
        <source>auto</source>
        <translation>自动</translation>
    </message>
    <message>
        <source>The last valid cam stays on screen.</source>
        <translation>屏幕上保留最后一个有效的凸轮。</translation>
    </message>
</context>
<context>
    <name>CamModel</name>
    <message>
        <source>edit cam</source>
        <translation>编辑凸轮</translation>
    </message>
    <message>
        <source>This design's cam cannot be made: no cam is shown.</source>
        <translation>此设计的凸轮无法求出：不显示凸轮。</translation>
    </message>
</context>
<context>
    <name>CamPlots</name>
    <message>
        <source>follower ψ</source>
        <translation>摆角 ψ</translation>
    </message>
    <message>
        <source>follower ω</source>
        <translation>角速度 ω</translation>
    </message>
    <message>
        <source>follower α</source>
        <translation>角加速度 α</translation>
    </message>
    <message>
        <source>pressure angle</source>
        <translation>压力角</translation>
    </message>
</context>
<context>
    <name>CamProfileView</name>
    <message>
        <source>cam angle δ = %1°, follower ψ = %2°</source>
        <translation>凸轮转角 δ = %1°，从动件摆角 ψ = %2°</translation>
    </message>
    <message>
        <source>Feed cam</source>
        <translation>进给凸轮</translation>
    </message>
</context>
<context>
    <name>CamTab</name>
    <message>
        <source>CSV…</source>
        <translation>CSV…</translation>
    </message>
    <message>
        <source>Image…</source>
        <translation>图像…</translation>
    </message>
    <message>
        <source>DXF…</source>
        <translation>DXF…</translation>
    </message>
    <message>
        <source>Base radius r0</source>
        <translation>基圆半径 r0</translation>
    </message>
    <message>
        <source>Centre distance a</source>
        <translation>中心距 a</translation>
    </message>
    <message>
        <source>Arm angle ψ0</source>
        <translation>初始摆角 ψ0</translation>
    </message>
    <message>
        <source>Roller side</source>
        <translation>滚子位于连心线</translation>
    </message>
    <message>
        <source>above</source>
        <translation>上方</translation>
    </message>
    <message>
        <source>below</source>
        <translation>下方</translation>
    </message>
    <message>
        <source>Max α rise</source>
        <translation>推程最大压力角</translation>
    </message>
    <message>
        <source>Max α return</source>
        <translation>回程最大压力角</translation>
    </message>
    <message>
        <source>ρmin (convex)</source>
        <translation>理论廓线最小曲率半径 ρmin</translation>
    </message>
    <message>
        <source>Roller r</source>
        <translation>滚子半径 r</translation>
    </message>
    <message>
        <source>Largest roller</source>
        <translation>最大滚子半径</translation>
    </message>
    <message>
        <source>Profile radius r0 − r … R1 − r</source>
        <translation>实际廓线半径 r0 − r … R1 − r</translation>
    </message>
    <message>
        <source>Base radius raised</source>
        <translation>基圆半径已增大</translation>
    </message>
    <message>
        <source>from %1 mm, to take the roller and clear the hub and the pivot boss</source>
        <translation>由 %1 mm 增大，以装下滚子并避开轮毂和摆动中心凸台</translation>
    </message>
    <message>
        <source>Rise at crank φ</source>
        <translation>推程起点曲柄转角 φ</translation>
    </message>
    <message>
        <source>Pressure angle</source>
        <translation>压力角</translation>
    </message>
    <message>
        <source>exceeds the allowance</source>
        <translation>超过许用值</translation>
    </message>
    <message>
        <source>CSV table (*.csv)</source>
        <translation>CSV 表格 (*.csv)</translation>
    </message>
    <message>
        <source>PNG image (*.png);;SVG drawing (*.svg)</source>
        <translation>PNG 图像 (*.png);;SVG 图形 (*.svg)</translation>
    </message>
    <message>
        <source>Export the cam</source>
        <translation>导出凸轮</translation>
    </message>
</context>
<context>
    <name>ClassDialog</name>
    <message>
        <source>Class course design</source>
        <translation>全班课程设计</translation>
    </message>
    <message>
        <source>DXF too</source>
        <translation>同时输出 DXF</translation>
    </message>
    <message>
        <source>Task table (CSV):</source>
        <translation>任务表（CSV）：</translation>
    </message>
    <message>
        <source>Base design:</source>
        <translation>基础设计：</translation>
    </message>
    <message>
        <source>Output folder:</source>
        <translation>输出文件夹：</translation>
    </message>
    <message>
        <source>Sheets:</source>
        <translation>图纸：</translation>
    </message>
    <message>
        <source>Line</source>
        <translation>行</translation>
    </message>
    <message>
        <source>Student</source>
        <translation>学生</translation>
    </message>
    <message>
        <source>Number</source>
        <translation>学号</translation>
    </message>
    <message>
        <source>Check</source>
        <translation>检查</translation>
    </message>
    <message>
        <source>Run</source>
        <translation>运行</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>取消</translation>
    </message>
    <message>
        <source>Open folder</source>
        <translation>打开文件夹</translation>
    </message>
    <message>
        <source>Browse…</source>
        <translation>浏览…</translation>
    </message>
    <message>
        <source>Task table</source>
        <translation>任务表</translation>
    </message>
    <message>
        <source>CSV (*.csv);;All files (*)</source>
        <translation>CSV (*.csv);;所有文件 (*)</translation>
    </message>
    <message>
        <source>Base design</source>
        <translation>基础设计</translation>
    </message>
    <message>
        <source>Designs (*.json);;All files (*)</source>
        <translation>设计文件 (*.json);;所有文件 (*)</translation>
    </message>
    <message>
        <source>Output folder</source>
        <translation>输出文件夹</translation>
    </message>
    <message>
        <source>The table cannot be used: %1</source>
        <translation>任务表无法使用：%1</translation>
    </message>
    <message>
        <source>ready</source>
        <translation>就绪</translation>
    </message>
    <message>
        <source>written</source>
        <translation>已写入</translation>
    </message>
    <message>
        <source>up to date, not written again</source>
        <translation>已是最新，未重写</translation>
    </message>
    <message>
        <source>failed: %1</source>
        <translation>失败：%1</translation>
    </message>
    <message>
        <source>not written (cancelled)</source>
        <translation>未写入（已取消）</translation>
    </message>
    <message>
        <source>not written</source>
        <translation>未写入</translation>
    </message>
    <message>
        <source>%1 students ready, %2 rows with errors (left out).</source>
        <translation>%1 名学生就绪，%2 行有错误（将跳过）。</translation>
    </message>
    <message>
        <source>Writing the class's files…</source>
        <translation>正在写入全班的文件…</translation>
    </message>
    <message>
        <source>Cancelling: the students being written are finished…</source>
        <translation>正在取消：正在写入的学生将先完成…</translation>
    </message>
    <message>
        <source>Cancelled: %1 students written, each complete.</source>
        <translation>已取消：已写入 %1 名学生，文件均完整。</translation>
    </message>
    <message>
        <source>Done: %1 students written; the task sheets and the answer key are in the folder.</source>
        <translation>完成：已写入 %1 名学生；任务书和参考答案在文件夹中。</translation>
    </message>
    <message>
        <source>Failed: %1</source>
        <translation>失败：%1</translation>
    </message>
    <message>
        <source>Notes (%1):</source>
        <translation>说明（%1 条）：</translation>
    </message>
</context>
<context>
    <name>ClassMessages</name>
    <message>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
    <message>
        <source>%1 line %2: %3</source>
        <translation>%1 第 %2 行：%3</translation>
    </message>
    <message>
        <source>%1 line %2, column %3: %4</source>
        <translation>%1 第 %2 行，%3 列：%4</translation>
    </message>
    <message>
        <source>%1 (got %2)</source>
        <translation>%1（输入的是 %2）</translation>
    </message>
    <message>
        <source>empty; every student needs one</source>
        <translation>为空；每名学生都须填写</translation>
    </message>
    <message>
        <source>must be one line of text without control characters</source>
        <translation>须为一行文字，不含控制字符</translation>
    </message>
    <message>
        <source>at most %1 characters</source>
        <translation>最多 %1 个字符</translation>
    </message>
    <message>
        <source>must be yes or no</source>
        <translation>须为 yes 或 no</translation>
    </message>
    <message>
        <source>%1 is outside the table's folder; put the design file beside the table</source>
        <translation>%1 不在任务表所在的文件夹内；请把设计文件放在任务表旁边</translation>
    </message>
    <message>
        <source>%1 cells, but the header names %2 columns</source>
        <translation>有 %1 个单元格，但表头有 %2 列</translation>
    </message>
    <message>
        <source>%1: required (or use %2 or %3)</source>
        <translation>%1：必须给出（或用 %2 或 %3）</translation>
    </message>
    <message>
        <source>%1: required</source>
        <translation>%1：必须给出</translation>
    </message>
    <message>
        <source>%1 is also on line %2; each student needs a number of their own</source>
        <translation>%1 与第 %2 行重复；每名学生须有自己的学号</translation>
    </message>
    <message>
        <source>the folder %1 is also line %2's; give one of them a number that differs in more than letter case and the characters a folder name cannot hold</source>
        <translation>文件夹 %1 与第 %2 行的相同；请给其中一人换一个学号，且不只是大小写或文件夹名不能含的字符不同</translation>
    </message>
    <message>
        <source>%1 is a number a spreadsheet wrote short, its digits lost; format the column as text and save the table again</source>
        <translation>%1 是电子表格缩写了的数字，已丢失数位；请把该列设为文本格式后重新保存表格</translation>
    </message>
    <message>
        <source>has no name</source>
        <translation>没有列名</translation>
    </message>
    <message>
        <source>named twice</source>
        <translation>列名重复</translation>
    </message>
    <message>
        <source>not a column; did you mean %1?</source>
        <translation>不是可用的列；是否指 %1？</translation>
    </message>
    <message>
        <source>not a column; see 'shaper design --help' for the options</source>
        <translation>不是可用的列；可用的列见 'shaper design --help'</translation>
    </message>
    <message>
        <source>no column %1</source>
        <translation>缺少 %1 列</translation>
    </message>
    <message>
        <source>not UTF-8 or GBK text; save it as "CSV UTF-8"</source>
        <translation>不是 UTF-8 或 GBK 文本；请另存为“CSV UTF-8”</translation>
    </message>
    <message>
        <source>more than %1 students; split the class into several tables</source>
        <translation>超过 %1 名学生；请把班级拆成几张表</translation>
    </message>
    <message>
        <source>larger than %1 MB; a class is at most %2 rows</source>
        <translation>大于 %1 MB；一个班最多 %2 行</translation>
    </message>
    <message>
        <source>empty; the first row names the columns (student, student-number, …)</source>
        <translation>为空；第一行须为列名（student、student-number 等）</translation>
    </message>
    <message>
        <source>no students; each row under the header is one student</source>
        <translation>没有学生；列名行之下每一行为一名学生</translation>
    </message>
    <message>
        <source>a quote opens a cell that no quote closes before the table ends; close it, or write a quote that belongs to the text twice</source>
        <translation>有一个引号开始的单元格直到表格结束都没有闭合；请补上闭合的引号，或把属于文字本身的引号写成两个</translation>
    </message>
    <message>
        <source>the speeds (column rpm)</source>
        <translation>转速（rpm 列）</translation>
    </message>
    <message>
        <source>the loads (columns lever-weight, lever-inertia, ram-weight, cut-force …)</source>
        <translation>载荷（lever-weight、lever-inertia、ram-weight、cut-force 等列）</translation>
    </message>
    <message>
        <source>the feed cam (columns arm, swing, pressure, rise, dwell, return)</source>
        <translation>进给凸轮（arm、swing、pressure、rise、dwell、return 列）</translation>
    </message>
    <message>
        <source>the gear pair (columns z1, z2, module)</source>
        <translation>齿轮副（z1、z2、module 列）</translation>
    </message>
    <message>
        <source>%1 and %2</source>
        <translation>%1和%2</translation>
    </message>
    <message>
        <source>, </source>
        <translation>、</translation>
    </message>
    <message>
        <source>lacks %1, which the course design needs; give them as columns or in --base</source>
        <translation>缺少课程设计所需的%1；请以列给出，或写在 --base 文件中</translation>
    </message>
    <message>
        <source>lacks %1, which the course design needs; give them as columns or in the design file</source>
        <translation>缺少课程设计所需的%1；请以列给出，或写在设计文件中</translation>
    </message>
    <message>
        <source>%1 from --base</source>
        <translation>%1，取自 --base 文件</translation>
    </message>
    <message>
        <source>%1 from the design file</source>
        <translation>%1，取自设计文件</translation>
    </message>
    <message>
        <source>%1: removed %2 of an earlier run, drawn from its data; this run writes no DXF</source>
        <translation>%1：已删除上次运行按其数据绘制的 %2；本次运行不输出 DXF</translation>
    </message>
    <message>
        <source>%1 holds an earlier run's files, not made from this table (its row, line %2, is bad) and not in its answer key; left as it was</source>
        <translation>%1 中是上次运行的文件，不是由本任务表生成的（其所在的第 %2 行有错误），也不在本次的参考答案中；已保持原样</translation>
    </message>
    <message>
        <source>%1 holds an earlier run's files, not made from this table (%2 has no row for it) and not in its answer key; left as it was</source>
        <translation>%1 中是上次运行的文件，不是由本任务表生成的（%2 中没有它的行），也不在本次的参考答案中；已保持原样</translation>
    </message>
    <message>
        <source>%1 read as %2</source>
        <translation>%1 已按 %2 编码读取</translation>
    </message>
    <message>
        <source>another 'shaper class' is writing into %1; let it finish, then run this one</source>
        <translation>另一个“全班课程设计”正在向 %1 写入；请等它结束后再运行本次</translation>
    </message>
    <message>
        <source>cannot write into %1: %2</source>
        <translation>无法写入文件夹 %1：%2</translation>
    </message>
    <message>
        <source>cannot write %1: %2</source>
        <translation>无法写入 %1：%2</translation>
    </message>
    <message>
        <source>it is not a folder</source>
        <translation>它不是文件夹</translation>
    </message>
    <message>
        <source>cannot make the folder %1: a file of that name is in the way; move it, then run the class again</source>
        <translation>无法创建文件夹 %1：已有同名文件挡住；请将其移走后重新运行本班</translation>
    </message>
    <message>
        <source>cannot make %1: %2</source>
        <translation>无法创建 %1：%2</translation>
    </message>
    <message>
        <source>%1 of %2 students not written (%3 bad rows, %4 failed).</source>
        <translation>%2 名学生中有 %1 名未写入（%3 行有错，%4 名失败）。</translation>
    </message>
</context>
<context>
    <name>ClassSheets</name>
    <message>
        <source>Course design task sheet</source>
        <translation>课程设计任务书</translation>
    </message>
    <message>
        <source>Quick-return mechanism of a shaper</source>
        <translation>牛头刨床导杆机构</translation>
    </message>
    <message>
        <source>Student</source>
        <translation>学生</translation>
    </message>
    <message>
        <source>Number</source>
        <translation>学号</translation>
    </message>
    <message>
        <source>Class</source>
        <translation>班级</translation>
    </message>
    <message>
        <source>Date</source>
        <translation>日期</translation>
    </message>
    <message>
        <source>The mechanism (sketch to scale, crank at 60°)</source>
        <translation>机构简图（按比例，曲柄在 60°）</translation>
    </message>
    <message>
        <source>Data set</source>
        <translation>设计数据</translation>
    </message>
    <message>
        <source>Quantity</source>
        <translation>名称</translation>
    </message>
    <message>
        <source>Symbol</source>
        <translation>符号</translation>
    </message>
    <message>
        <source>Value</source>
        <translation>数值</translation>
    </message>
    <message>
        <source>Unit</source>
        <translation>单位</translation>
    </message>
    <message>
        <source>Crank speed</source>
        <translation>曲柄转速</translation>
    </message>
    <message>
        <source>Frame O_2O_4</source>
        <translation>机架 O_2O_4</translation>
    </message>
    <message>
        <source>Crank O_2A</source>
        <translation>曲柄 O_2A</translation>
    </message>
    <message>
        <source>Lever O_4B</source>
        <translation>导杆 O_4B</translation>
    </message>
    <message>
        <source>Rod BC</source>
        <translation>连杆 BC</translation>
    </message>
    <message>
        <source>Time ratio</source>
        <translation>行程速比系数</translation>
    </message>
    <message>
        <source>Stroke</source>
        <translation>行程</translation>
    </message>
    <message>
        <source>Lever's centre of mass O_4S_4</source>
        <translation>导杆质心 O_4S_4</translation>
    </message>
    <message>
        <source>Lever weight</source>
        <translation>导杆重量</translation>
    </message>
    <message>
        <source>Lever moment of inertia</source>
        <translation>导杆转动惯量</translation>
    </message>
    <message>
        <source>Ram weight</source>
        <translation>滑枕重量</translation>
    </message>
    <message>
        <source>Cutting force</source>
        <translation>切削力</translation>
    </message>
    <message>
        <source>Height of the cutting force</source>
        <translation>切削力作用高度</translation>
    </message>
    <message>
        <source>Guide line</source>
        <translation>导路高度</translation>
    </message>
    <message>
        <source>Follower arm</source>
        <translation>从动件摆臂长</translation>
    </message>
    <message>
        <source>Follower swing</source>
        <translation>从动件最大摆角</translation>
    </message>
    <message>
        <source>Allowed pressure angle</source>
        <translation>许用压力角</translation>
    </message>
    <message>
        <source>Rise</source>
        <translation>推程运动角</translation>
    </message>
    <message>
        <source>Outer dwell</source>
        <translation>远休止角</translation>
    </message>
    <message>
        <source>Return</source>
        <translation>回程运动角</translation>
    </message>
    <message>
        <source>Pinion teeth</source>
        <translation>小齿轮齿数</translation>
    </message>
    <message>
        <source>Gear teeth</source>
        <translation>大齿轮齿数</translation>
    </message>
    <message>
        <source>Module</source>
        <translation>模数</translation>
    </message>
    <message>
        <source>Deliver</source>
        <translation>应交成果</translation>
    </message>
    <message>
        <source>Answer key</source>
        <translation>参考答案</translation>
    </message>
    <message>
        <source>page %1/%2</source>
        <translation>第 %1/%2 页</translation>
    </message>
    <message>
        <source>No.</source>
        <translation>序号</translation>
    </message>
    <message>
        <source>failed checks</source>
        <translation>未通过的校核</translation>
    </message>
    <message>
        <source>Rod side: C ahead of B while cutting</source>
        <translation>连杆位置（切削时 C 在 B 之前）</translation>
    </message>
    <message>
        <source>leading</source>
        <translation>前置</translation>
    </message>
    <message>
        <source>speed</source>
        <translation>转速</translation>
    </message>
    <message>
        <source>none</source>
        <translation>无</translation>
    </message>
    <message>
        <source>, </source>
        <translation>、</translation>
    </message>
    <message>
        <source>cam pressure angle</source>
        <translation>凸轮压力角</translation>
    </message>
    <message>
        <source>undercut 1</source>
        <translation>齿轮1根切</translation>
    </message>
    <message>
        <source>undercut 2</source>
        <translation>齿轮2根切</translation>
    </message>
    <message>
        <source>tip 1</source>
        <translation>齿轮1齿顶</translation>
    </message>
    <message>
        <source>tip 2</source>
        <translation>齿轮2齿顶</translation>
    </message>
    <message>
        <source>contact ratio</source>
        <translation>重合度</translation>
    </message>
    <message>
        <source>interference 1</source>
        <translation>齿轮1干涉</translation>
    </message>
    <message>
        <source>interference 2</source>
        <translation>齿轮2干涉</translation>
    </message>
    <message>
        <source>Coefficient of speed fluctuation</source>
        <translation>速度不均匀系数</translation>
    </message>
    <message>
        <source>not counted</source>
        <translation>不计</translation>
    </message>
    <message>
        <source>Other rotating parts</source>
        <translation>其他转动构件</translation>
    </message>
    <message>
        <source>Base radius</source>
        <translation>基圆半径</translation>
    </message>
    <message>
        <source>Centre distance of the cam</source>
        <translation>凸轮中心距</translation>
    </message>
    <message>
        <source>Shift factors</source>
        <translation>变位系数</translation>
    </message>
    <message>
        <source>Addendum</source>
        <translation>齿顶高系数</translation>
    </message>
    <message>
        <source>Clearance</source>
        <translation>顶隙系数</translation>
    </message>
    <message>
        <source>Design report (00-report.pdf)</source>
        <translation>设计说明书（00-report.pdf）</translation>
    </message>
    <message>
        <source>Motion analysis sheet (01-motion)</source>
        <translation>运动分析图（01-motion）</translation>
    </message>
    <message>
        <source>Kinetostatic analysis sheet (02-kinetostatic)</source>
        <translation>动态静力分析图（02-kinetostatic）</translation>
    </message>
    <message>
        <source>Feed cam sheet (03-cam)</source>
        <translation>凸轮机构设计图（03-cam）</translation>
    </message>
    <message>
        <source>Gear meshing sheet (04-gear)</source>
        <translation>齿轮啮合图（04-gear）</translation>
    </message>
</context>
<context>
    <name>Columns</name>
    <message>
        <source>yes</source>
        <translation>是</translation>
    </message>
    <message>
        <source>no</source>
        <translation>否</translation>
    </message>
    <message>
        <source>n (r/min)</source>
        <translation>n (r/min)</translation>
    </message>
    <message>
        <source>φ (°)</source>
        <translation>φ (°)</translation>
    </message>
    <message>
        <source>t (s)</source>
        <translation>t (s)</translation>
    </message>
    <message>
        <source>ram x (mm)</source>
        <translation>滑枕位移 x (mm)</translation>
    </message>
    <message>
        <source>ram v (m/s)</source>
        <translation>滑枕速度 v (m/s)</translation>
    </message>
    <message>
        <source>ram a (m/s²)</source>
        <translation>滑枕加速度 a (m/s²)</translation>
    </message>
    <message>
        <source>lever ψ (°)</source>
        <translation>导杆角 ψ (°)</translation>
    </message>
    <message>
        <source>lever ω4 (rad/s)</source>
        <translation>导杆 ω4 (rad/s)</translation>
    </message>
    <message>
        <source>lever α4 (rad/s²)</source>
        <translation>导杆 α4 (rad/s²)</translation>
    </message>
    <message>
        <source>block v_A3A4 (m/s)</source>
        <translation>滑块相对速度 v_A3A4 (m/s)</translation>
    </message>
    <message>
        <source>Coriolis a^k (m/s²)</source>
        <translation>哥氏加速度 a^k (m/s²)</translation>
    </message>
    <message>
        <source>rod λ (°)</source>
        <translation>连杆角 λ (°)</translation>
    </message>
    <message>
        <source>rod ω5 (rad/s)</source>
        <translation>连杆 ω5 (rad/s)</translation>
    </message>
    <message>
        <source>rod α5 (rad/s²)</source>
        <translation>连杆 α5 (rad/s²)</translation>
    </message>
    <message>
        <source>pressure angle (°)</source>
        <translation>压力角 (°)</translation>
    </message>
    <message>
        <source>crank torque M (N·m)</source>
        <translation>曲柄驱动力矩 M (N·m)</translation>
    </message>
    <message>
        <source>power (W)</source>
        <translation>功率 (W)</translation>
    </message>
    <message>
        <source>O2 x (N)</source>
        <translation>O2 x (N)</translation>
    </message>
    <message>
        <source>O2 y (N)</source>
        <translation>O2 y (N)</translation>
    </message>
    <message>
        <source>pin A x (N)</source>
        <translation>销 A x (N)</translation>
    </message>
    <message>
        <source>pin A y (N)</source>
        <translation>销 A y (N)</translation>
    </message>
    <message>
        <source>A x (N)</source>
        <translation>A x (N)</translation>
    </message>
    <message>
        <source>A y (N)</source>
        <translation>A y (N)</translation>
    </message>
    <message>
        <source>A normal (N)</source>
        <translation>A 法向力 (N)</translation>
    </message>
    <message>
        <source>O4 x (N)</source>
        <translation>O4 x (N)</translation>
    </message>
    <message>
        <source>O4 y (N)</source>
        <translation>O4 y (N)</translation>
    </message>
    <message>
        <source>B x (N)</source>
        <translation>B x (N)</translation>
    </message>
    <message>
        <source>B y (N)</source>
        <translation>B y (N)</translation>
    </message>
    <message>
        <source>C x (N)</source>
        <translation>C x (N)</translation>
    </message>
    <message>
        <source>C y (N)</source>
        <translation>C y (N)</translation>
    </message>
    <message>
        <source>guide N (N)</source>
        <translation>导路反力 N (N)</translation>
    </message>
    <message>
        <source>guide moment (N·m)</source>
        <translation>导路力矩 (N·m)</translation>
    </message>
    <message>
        <source>N offset (mm)</source>
        <translation>N 作用点偏距 (mm)</translation>
    </message>
    <message>
        <source>guide rear end (N)</source>
        <translation>导路后端 (N)</translation>
    </message>
    <message>
        <source>guide front end (N)</source>
        <translation>导路前端 (N)</translation>
    </message>
    <message>
        <source>ram tilted on the guide ends</source>
        <translation>滑枕倾斜支承于导路两端</translation>
    </message>
    <message>
        <source>cutting force P (N)</source>
        <translation>切削力 P (N)</translation>
    </message>
    <message>
        <source>limit position, start of working stroke</source>
        <translation>极限位置（工作行程起点）</translation>
    </message>
    <message>
        <source>limit position, end of working stroke</source>
        <translation>极限位置（工作行程终点）</translation>
    </message>
    <message>
        <source>cut starts (cutting)</source>
        <translation>切削开始（计入切削力）</translation>
    </message>
    <message>
        <source>cut ends (cutting)</source>
        <translation>切削结束（计入切削力）</translation>
    </message>
    <message>
        <source>max cutting speed</source>
        <translation>最大切削速度</translation>
    </message>
    <message>
        <source>max return speed</source>
        <translation>最大回程速度</translation>
    </message>
    <message>
        <source>Ram</source>
        <translation>滑枕</translation>
    </message>
    <message>
        <source>Lever and block</source>
        <translation>导杆与滑块</translation>
    </message>
    <message>
        <source>Connecting rod</source>
        <translation>连杆</translation>
    </message>
    <message>
        <source>Crank torque, cutting force and guide</source>
        <translation>曲柄驱动力矩、切削力与导路反力</translation>
    </message>
    <message>
        <source>Joint forces at O2 and A</source>
        <translation>O2、A 处运动副反力</translation>
    </message>
    <message>
        <source>Joint forces at O4, B and C</source>
        <translation>O4、B、C 处运动副反力</translation>
    </message>
</context>
<context>
    <name>ComparePlots</name>
    <message>
        <source>Ram x (mm)</source>
        <translation>滑枕 x (mm)</translation>
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
        <source>Torque (N·m)</source>
        <translation>驱动力矩 (N·m)</translation>
    </message>
    <message>
        <source>Crank angle (°)</source>
        <translation>曲柄转角 (°)</translation>
    </message>
</context>
<context>
    <name>CompareView</name>
    <message>
        <source>At most %1 designs can be compared.</source>
        <translation>最多可比较 %1 个设计。</translation>
    </message>
    <message>
        <source>This design is already compared, as “%1”.</source>
        <translation>此设计已在比较中，名为“%1”。</translation>
    </message>
    <message>
        <source>chord</source>
        <translation>弦线</translation>
    </message>
    <message>
        <source>sagitta</source>
        <translation>矢高中点</translation>
    </message>
    <message>
        <source>trailing rod</source>
        <translation>后置连杆</translation>
    </message>
    <message>
        <source>leading rod</source>
        <translation>前置连杆</translation>
    </message>
    <message>
        <source>other loads</source>
        <translation>载荷不同</translation>
    </message>
    <message>
        <source>%1 modified, %2 (snapshot %3)</source>
        <translation>%1（已修改），%2（快照 %3）</translation>
    </message>
    <message>
        <source>Design on screen, %2 (snapshot %3)</source>
        <translation>当前设计，%2（快照 %3）</translation>
    </message>
    <message>
        <source>Could not open the design: %1</source>
        <translation>无法打开设计：%1</translation>
    </message>
    <message>
        <source>Add design files</source>
        <translation>添加设计文件</translation>
    </message>
    <message>
        <source>Shaper designs (*.shaper.json *.json);;All files (*)</source>
        <translation>牛头刨床设计 (*.shaper.json *.json);;所有文件 (*)</translation>
    </message>
    <message>
        <source>Pick 2 to 6 designs: select them in the library and press Compare, or add the design on screen or design files here.</source>
        <translation>请选择 2 至 6 个设计：在设计库中选中后点击“比较”，或在此添加当前设计或设计文件。</translation>
    </message>
    <message>
        <source>Best in this row</source>
        <translation>本行最优</translation>
    </message>
    <message>
        <source>There is nothing to export yet: pick 2 to 6 designs to compare first.</source>
        <translation>还没有可导出的内容：请先选择 2 到 6 个设计进行比较。</translation>
    </message>
    <message>
        <source>Design comparison</source>
        <translation>设计比较</translation>
    </message>
    <message>
        <source>Comparison at %1 r/min; differences from “%2” in brackets; ★ best</source>
        <translation>转速 %1 r/min 下的比较；括号内为与“%2”的差值；★ 为最优</translation>
    </message>
    <message>
        <source>Export comparison to CSV</source>
        <translation>导出比较结果为 CSV</translation>
    </message>
    <message>
        <source>CSV files (*.csv)</source>
        <translation>CSV 文件 (*.csv)</translation>
    </message>
    <message>
        <source>Export comparison image</source>
        <translation>导出比较图像</translation>
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
        <source>Compare designs</source>
        <translation>比较设计</translation>
    </message>
    <message>
        <source>Add design on screen</source>
        <translation>添加当前设计</translation>
    </message>
    <message>
        <source>Adds a snapshot of the design on screen, named with its time: later edits do not change it</source>
        <translation>添加当前设计的快照，以添加时间命名：之后的修改不会改变它</translation>
    </message>
    <message>
        <source>Add file…</source>
        <translation>添加文件…</translation>
    </message>
    <message>
        <source>Remove</source>
        <translation>移除</translation>
    </message>
    <message>
        <source>Speed (r/min):</source>
        <translation>转速 (r/min)：</translation>
    </message>
    <message>
        <source>Export CSV…</source>
        <translation>导出 CSV…</translation>
    </message>
    <message>
        <source>Export PNG/SVG…</source>
        <translation>导出 PNG/SVG…</translation>
    </message>
</context>
<context>
    <name>CourseExport</name>
    <message>
        <source>the speeds</source>
        <translation>曲柄转速</translation>
    </message>
    <message>
        <source>the loads</source>
        <translation>载荷</translation>
    </message>
    <message>
        <source>the feed cam</source>
        <translation>进给凸轮</translation>
    </message>
    <message>
        <source>the gear pair</source>
        <translation>齿轮副</translation>
    </message>
    <message>
        <source>the design</source>
        <translation>该设计</translation>
    </message>
    <message>
        <source>The design lacks what the course design needs: %1. Nothing was written.</source>
        <translation>设计缺少课程设计所需的内容：%1。未写入任何文件。</translation>
    </message>
    <message>
        <source>Nothing can be written into this folder; choose another. Nothing was written.</source>
        <translation>无法写入此文件夹，请另选一个。未写入任何文件。</translation>
    </message>
    <message>
        <source>The course design cannot be made: %1. Nothing was written.</source>
        <translation>无法生成课程设计：%1。未写入任何文件。</translation>
    </message>
    <message>
        <source>Writing the course design…</source>
        <translation>正在写入课程设计…</translation>
    </message>
    <message>
        <source>Export course design</source>
        <translation>导出课程设计</translation>
    </message>
    <message>
        <source>Cancelled: %1 of %2 files written, each complete.</source>
        <translation>已取消：%2 个文件中已写入 %1 个，均完整。</translation>
    </message>
    <message>
        <source>No font with Chinese characters is installed: install one (on Debian/Ubuntu: fonts-noto-cjk) or switch the language to English.</source>
        <translation>未安装含中文字形的字体：请安装一个（Debian/Ubuntu 上为 fonts-noto-cjk），或把语言切换为英文。</translation>
    </message>
    <message>
        <source>Could not write %1: %2</source>
        <translation>无法写入 %1：%2</translation>
    </message>
    <message>
        <source>The course design cannot be made: %1.</source>
        <translation>无法生成课程设计：%1。</translation>
    </message>
    <message>
        <source>The %1 files written before it are complete.</source>
        <translation>此前写入的 %1 个文件均完整。</translation>
    </message>
    <message>
        <source>Export course design: choose a folder</source>
        <translation>导出课程设计：选择文件夹</translation>
    </message>
    <message>
        <source>Nothing was written.</source>
        <translation>未写入任何文件。</translation>
    </message>
</context>
<context>
    <name>CourseOptionsDialog</name>
    <message>
        <source>Export course design</source>
        <translation>导出课程设计</translation>
    </message>
    <message>
        <source>Each sheet as DXF too, beside its PDF</source>
        <translation>每张图纸另存 DXF（与 PDF 同目录）</translation>
    </message>
    <message>
        <source>%1 r/min</source>
        <translation>%1 r/min</translation>
    </message>
    <message>
        <source>Paper of the sheets:</source>
        <translation>图纸图幅：</translation>
    </message>
    <message>
        <source>Sheets at crank speed:</source>
        <translation>图纸所用曲柄转速：</translation>
    </message>
    <message>
        <source>CAD texts of the DXFs:</source>
        <translation>DXF 的 CAD 文字：</translation>
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
        <source>Add a crank speed (at most %1)</source>
        <translation>添加一个曲柄转速（最多 %1 个）</translation>
    </message>
    <message>
        <source>Remove the selected crank speed</source>
        <translation>删除选中的曲柄转速</translation>
    </message>
    <message>
        <source>Synthesis inputs</source>
        <translation>综合输入</translation>
    </message>
    <message>
        <source>Link lengths</source>
        <translation>杆长</translation>
    </message>
    <message>
        <source>The last valid design stays on screen.</source>
        <translation>屏幕上保留最后一个有效设计。</translation>
    </message>
</context>
<context>
    <name>DimensionLayer</name>
    <message>
        <source>L2 = {0}</source>
        <translation>L2 = {0}</translation>
    </message>
    <message>
        <source>h = {0}</source>
        <translation>h = {0}</translation>
    </message>
    <message>
        <source>L3 = {0}</source>
        <translation>L3 = {0}</translation>
    </message>
    <message>
        <source>L1 = {0}</source>
        <translation>L1 = {0}</translation>
    </message>
    <message>
        <source>H = {0}</source>
        <translation>H = {0}</translation>
    </message>
</context>
<context>
    <name>Docks</name>
    <message>
        <source>Inputs</source>
        <translation>输入</translation>
    </message>
    <message>
        <source>Results</source>
        <translation>计算结果</translation>
    </message>
    <message>
        <source>Mechanism</source>
        <translation>机构简图</translation>
    </message>
    <message>
        <source>Vector diagrams</source>
        <translation>矢量多边形</translation>
    </message>
    <message>
        <source>Design library</source>
        <translation>设计库</translation>
    </message>
</context>
<context>
    <name>Document</name>
    <message>
        <source>Could not open the design: %1</source>
        <translation>无法打开设计：%1</translation>
    </message>
    <message>
        <source>Could not open %1: %2</source>
        <translation>无法打开 %1：%2</translation>
    </message>
    <message>
        <source>Could not save %1: %2</source>
        <translation>无法保存 %1：%2</translation>
    </message>
    <message>
        <source>Could not write %1: a scheme for CAD is written as DXF (.dxf)</source>
        <translation>无法写入 %1：供 CAD 使用的机构简图以 DXF 格式 (.dxf) 保存</translation>
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
        <source>Save the last valid design instead? The invalid input is then reset to it.</source>
        <translation>改为保存上一个有效设计吗？无效的输入将恢复为该设计的值。</translation>
    </message>
    <message>
        <source>Export the results of the last valid design instead?</source>
        <translation>改为导出上一个有效设计的结果吗？</translation>
    </message>
    <message>
        <source>Invalid input</source>
        <translation>输入无效</translation>
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
        <source>Export scheme as DXF</source>
        <translation>导出机构简图为 DXF</translation>
    </message>
    <message>
        <source>CSV files (*.csv)</source>
        <translation>CSV 文件 (*.csv)</translation>
    </message>
</context>
<context>
    <name>Drawing</name>
    <message>
        <source>Design</source>
        <translation>设计名称</translation>
    </message>
    <message>
        <source>Scale</source>
        <translation>比例</translation>
    </message>
    <message>
        <source>Sheet</source>
        <translation>张次</translation>
    </message>
    <message>
        <source>Drawn</source>
        <translation>制图</translation>
    </message>
    <message>
        <source>Date</source>
        <translation>日期</translation>
    </message>
    <message>
        <source>Checked</source>
        <translation>审核</translation>
    </message>
    <message>
        <source>Approved</source>
        <translation>批准</translation>
    </message>
    <message>
        <source>Number</source>
        <translation>学号</translation>
    </message>
    <message>
        <source>Class</source>
        <translation>班级</translation>
    </message>
    <message>
        <source>Supervisor</source>
        <translation>指导教师</translation>
    </message>
    <message>
        <source>Motion analysis</source>
        <translation>运动分析图</translation>
    </message>
    <message>
        <source>Kinematic diagram at {count} positions, μ_l = {mu} m/mm ({scale})</source>
        <translation>机构运动简图（{count} 个位置），μ_l = {mu} m/mm（{scale}）</translation>
    </message>
    <message>
        <source>μ_s = {mu} m/mm</source>
        <translation>μ_s = {mu} m/mm</translation>
    </message>
    <message>
        <source>μ_v = {mu} (m/s)/mm</source>
        <translation>μ_v = {mu} (m/s)/mm</translation>
    </message>
    <message>
        <source>μ_a = {mu} (m/s²)/mm</source>
        <translation>μ_a = {mu} (m/s²)/mm</translation>
    </message>
    <message>
        <source>Velocity polygon, φ = {angle}°, μ_v = {mu} (m/s)/mm</source>
        <translation>速度多边形，φ = {angle}°，μ_v = {mu} (m/s)/mm</translation>
    </message>
    <message>
        <source>Acceleration polygon, φ = {angle}°, μ_a = {mu} (m/s²)/mm</source>
        <translation>加速度多边形，φ = {angle}°，μ_a = {mu} (m/s²)/mm</translation>
    </message>
    <message>
        <source>Crank O_2A, L_1</source>
        <translation>曲柄 O_2A，L_1</translation>
    </message>
    <message>
        <source>Frame O_2O_4, L_2</source>
        <translation>机架 O_2O_4，L_2</translation>
    </message>
    <message>
        <source>Lever O_4B, L_3</source>
        <translation>导杆 O_4B，L_3</translation>
    </message>
    <message>
        <source>Rod BC, L_4</source>
        <translation>连杆 BC，L_4</translation>
    </message>
    <message>
        <source>Ram displacement, velocity and acceleration, n = {rpm} r/min</source>
        <translation>滑枕位移、速度、加速度线图，n = {rpm} r/min</translation>
    </message>
    <message>
        <source>s/mm</source>
        <translation>s/mm</translation>
    </message>
    <message>
        <source>v/(m/s)</source>
        <translation>v/(m/s)</translation>
    </message>
    <message>
        <source>a/(m/s²)</source>
        <translation>a/(m/s²)</translation>
    </message>
    <message>
        <source>Position</source>
        <translation>位置</translation>
    </message>
    <message>
        <source>φ/(°)</source>
        <translation>φ/(°)</translation>
    </message>
    <message>
        <source>Main dimensions</source>
        <translation>主要尺寸</translation>
    </message>
    <message>
        <source>Kinetostatic analysis</source>
        <translation>动态静力分析图</translation>
    </message>
    <message>
        <source>Loads and joint forces, φ = {angle}°</source>
        <translation>载荷与运动副反力，φ = {angle}°</translation>
    </message>
    <message>
        <source>Driving torque on the crank M over φ, mean M_m dashed, n = {rpm} r/min</source>
        <translation>曲柄驱动力矩 M–φ 曲线，虚线为平均值 M_m，n = {rpm} r/min</translation>
    </message>
    <message>
        <source>Energy ∫(M − M_m)dφ over φ, ΔW_max = {dw} J</source>
        <translation>盈亏功 ∫(M − M_m)dφ–φ 曲线，ΔW_max = {dw} J</translation>
    </message>
    <message>
        <source>M/(N·m)</source>
        <translation>M/(N·m)</translation>
    </message>
    <message>
        <source>E/J</source>
        <translation>E/J</translation>
    </message>
    <message>
        <source>Feed cam</source>
        <translation>进给凸轮</translation>
    </message>
    <message>
        <source>Cam profile by inversion, μ_l = {mu} m/mm ({scale})</source>
        <translation>反转法绘制凸轮廓线，μ_l = {mu} m/mm（{scale}）</translation>
    </message>
    <message>
        <source>Actual profile thick, pitch curve dash-dot, the follower at δ = 0; the cam turns clockwise</source>
        <translation>实际廓线粗实线，理论廓线点画线，从动件位于 δ = 0；凸轮顺时针转动</translation>
    </message>
    <message>
        <source>Follower angle, angular velocity and acceleration over the cam angle, n = {rpm} r/min</source>
        <translation>从动件摆角、角速度、角加速度线图，n = {rpm} r/min</translation>
    </message>
    <message>
        <source>Pressure angle over the cam angle, allowances [α] dashed</source>
        <translation>压力角线图，许用压力角 [α] 为虚线</translation>
    </message>
    <message>
        <source>ψ/(°)</source>
        <translation>ψ/(°)</translation>
    </message>
    <message>
        <source>ω/(rad/s)</source>
        <translation>ω/(rad/s)</translation>
    </message>
    <message>
        <source>α/(rad/s²)</source>
        <translation>α/(rad/s²)</translation>
    </message>
    <message>
        <source>α/(°)</source>
        <translation>α/(°)</translation>
    </message>
    <message>
        <source>δ/(°)</source>
        <translation>δ/(°)</translation>
    </message>
    <message>
        <source>μ_ψ = {mu} °/mm</source>
        <translation>μ_ψ = {mu} °/mm</translation>
    </message>
    <message>
        <source>μ_ω = {mu} (rad/s)/mm</source>
        <translation>μ_ω = {mu} (rad/s)/mm</translation>
    </message>
    <message>
        <source>μ_α = {mu} (rad/s²)/mm</source>
        <translation>μ_α = {mu} (rad/s²)/mm</translation>
    </message>
    <message>
        <source>μ_α = {mu} °/mm</source>
        <translation>μ_α = {mu} °/mm</translation>
    </message>
    <message>
        <source>μ_δ = {mu} °/mm</source>
        <translation>μ_δ = {mu} °/mm</translation>
    </message>
    <message>
        <source>δ_0 = {deg}°</source>
        <translation>δ_0 = {deg}°</translation>
    </message>
    <message>
        <source>δ_s = {deg}°</source>
        <translation>δ_s = {deg}°</translation>
    </message>
    <message>
        <source>δ_0′ = {deg}°</source>
        <translation>δ_0′ = {deg}°</translation>
    </message>
    <message>
        <source>δ_s′ = {deg}°</source>
        <translation>δ_s′ = {deg}°</translation>
    </message>
    <message>
        <source>Swing ψ_max</source>
        <translation>最大摆角 ψ_max</translation>
    </message>
    <message>
        <source>Rise δ_0, law</source>
        <translation>推程运动角 δ_0，运动规律</translation>
    </message>
    <message>
        <source>Outer dwell δ_s</source>
        <translation>远休止角 δ_s</translation>
    </message>
    <message>
        <source>Return δ_0′, law</source>
        <translation>回程运动角 δ_0′，运动规律</translation>
    </message>
    <message>
        <source>Inner dwell δ_s′</source>
        <translation>近休止角 δ_s′</translation>
    </message>
    <message>
        <source>Base radius r_0 (pitch curve)</source>
        <translation>理论廓线基圆半径 r_0</translation>
    </message>
    <message>
        <source>Initial arm angle ψ_0</source>
        <translation>初始摆角 ψ_0</translation>
    </message>
    <message>
        <source>Min convex radius ρ_min</source>
        <translation>理论廓线最小外凸曲率半径 ρ_min</translation>
    </message>
    <message>
        <source>Profile base radius r_0 − r</source>
        <translation>实际廓线基圆半径 r_0 − r</translation>
    </message>
    <message>
        <source>Cam data and results</source>
        <translation>凸轮设计数据与结果</translation>
    </message>
    <message>
        <source>Quantity</source>
        <translation>名称</translation>
    </message>
    <message>
        <source>Follower arm l</source>
        <translation>从动件摆臂长 l</translation>
    </message>
    <message>
        <source>Allowed pressure angle rise / return</source>
        <translation>许用压力角 推程 / 回程</translation>
    </message>
    <message>
        <source>Cam speed n</source>
        <translation>凸轮转速 n</translation>
    </message>
    <message>
        <source>Centre distance a</source>
        <translation>中心距 a</translation>
    </message>
    <message>
        <source>Roller side of the line of centres</source>
        <translation>滚子位于连心线</translation>
    </message>
    <message>
        <source>above</source>
        <translation>上方</translation>
    </message>
    <message>
        <source>below</source>
        <translation>下方</translation>
    </message>
    <message>
        <source>Max pressure angle rise / return</source>
        <translation>最大压力角 推程 / 回程</translation>
    </message>
    <message>
        <source>Roller radius r</source>
        <translation>滚子半径 r</translation>
    </message>
    <message>
        <source>Pressure angle allowance</source>
        <translation>压力角许用值</translation>
    </message>
    <message>
        <source>EXCEEDED</source>
        <translation>超过许用值</translation>
    </message>
    <message>
        <source>Follower ω_max / α_max</source>
        <translation>从动件 ω_max / α_max</translation>
    </message>
    <message>
        <source>Rise starts at crank angle</source>
        <translation>推程起点曲柄转角</translation>
    </message>
    <message>
        <source>parabolic</source>
        <translation>等加速等减速</translation>
    </message>
    <message>
        <source>cosine</source>
        <translation>余弦加速度</translation>
    </message>
    <message>
        <source>sine</source>
        <translation>正弦加速度</translation>
    </message>
    <message>
        <source>3-4-5</source>
        <translation>3-4-5 多项式</translation>
    </message>
    <message>
        <source>Flywheel</source>
        <translation>飞轮</translation>
    </message>
    <message>
        <source>Value</source>
        <translation>数值</translation>
    </message>
    <message>
        <source>μ_l = {mu} m/mm ({scale}), μ_F = {mu_f} N/mm</source>
        <translation>μ_l = {mu} m/mm（{scale}），μ_F = {mu_f} N/mm</translation>
    </message>
    <message>
        <source>Force polygon of the ram group, φ = {angle}°, μ_F = {mu_f} N/mm</source>
        <translation>滑枕杆组的力多边形，φ = {angle}°，μ_F = {mu_f} N/mm</translation>
    </message>
    <message>
        <source>Force polygon of the lever (link 4), φ = {angle}°, μ_F = {mu_f} N/mm</source>
        <translation>导杆（构件 4）的力多边形，φ = {angle}°，μ_F = {mu_f} N/mm</translation>
    </message>
    <message>
        <source>μ_M = {mu} (N·m)/mm</source>
        <translation>μ_M = {mu} (N·m)/mm</translation>
    </message>
    <message>
        <source>μ_E = {mu} J/mm</source>
        <translation>μ_E = {mu} J/mm</translation>
    </message>
    <message>
        <source>μ_φ = {mu} °/mm</source>
        <translation>μ_φ = {mu} °/mm</translation>
    </message>
    <message>
        <source>Mean driving torque M_m</source>
        <translation>平均驱动力矩 M_m</translation>
    </message>
    <message>
        <source>Largest driving torque</source>
        <translation>最大驱动力矩</translation>
    </message>
    <message>
        <source>Mean power (before efficiency)</source>
        <translation>平均功率（未计效率）</translation>
    </message>
    <message>
        <source>Energy fluctuation ΔW_max</source>
        <translation>最大盈亏功 ΔW_max</translation>
    </message>
    <message>
        <source>Coefficient of speed fluctuation δ</source>
        <translation>速度不均匀系数 δ</translation>
    </message>
    <message>
        <source>Flywheel J_F = ΔW_max/(ω²δ)</source>
        <translation>飞轮 J_F = ΔW_max/(ω²δ)</translation>
    </message>
    <message>
        <source>Mean reduced inertia J_e</source>
        <translation>平均等效转动惯量 J_e</translation>
    </message>
    <message>
        <source>Flywheel to add J_F − J_e</source>
        <translation>需加飞轮 J_F − J_e</translation>
    </message>
    <message>
        <source>Rotating parts J_c at the crank</source>
        <translation>其他转动构件等效到曲柄 J_c</translation>
    </message>
    <message>
        <source>Flywheel needed J_F − J_c</source>
        <translation>所需飞轮 J_F − J_c</translation>
    </message>
    <message>
        <source>Flywheel to add J_F − J_c − J_e</source>
        <translation>需加飞轮 J_F − J_c − J_e</translation>
    </message>
    <message>
        <source>none needed (J_c ≥ J_F)</source>
        <translation>无需飞轮 (J_c ≥ J_F)</translation>
    </message>
    <message>
        <source>Guide reaction N, φ = {angle}°</source>
        <translation>导路反力 N，φ = {angle}°</translation>
    </message>
    <message>
        <source>{n} N, {x} mm from C</source>
        <translation>{n} N，距 C {x} mm</translation>
    </message>
    <message>
        <source>Drawn {mm} mm long, not to μ_F:</source>
        <translation>画成 {mm} mm 长，未按 μ_F：</translation>
    </message>
    <message>
        <source>Guide ends rear / front, φ = {angle}°</source>
        <translation>导路后端 / 前端，φ = {angle}°</translation>
    </message>
    <message>
        <source>{rear} N / {front} N</source>
        <translation>{rear} N / {front} N</translation>
    </message>
    <message>
        <source>Stroke H</source>
        <translation>行程 H</translation>
    </message>
    <message>
        <source>Guide above O_2, h</source>
        <translation>导路距 O_2 的高度 h</translation>
    </message>
    <message>
        <source>Time ratio K</source>
        <translation>行程速比系数 K</translation>
    </message>
    <message>
        <source>Extreme-position angle θ</source>
        <translation>极位夹角 θ</translation>
    </message>
    <message>
        <source>Crank speed n</source>
        <translation>曲柄转速 n</translation>
    </message>
    <message>
        <source>Gear meshing</source>
        <translation>齿轮啮合图</translation>
    </message>
    <message>
        <source>The gear pair in mesh, μ_l = {mu} m/mm ({scale})</source>
        <translation>齿轮啮合图，μ_l = {mu} m/mm（{scale}）</translation>
    </message>
    <message>
        <source>Teeth as the rack cuts them; the pinion 1 drives counter-clockwise</source>
        <translation>齿廓按齿条刀具范成（渐开线与过渡曲线）；小齿轮 1 逆时针转动为主动轮</translation>
    </message>
    <message>
        <source>Gear pair data and results</source>
        <translation>齿轮传动参数与计算结果</translation>
    </message>
    <message>
        <source>Pinion 1</source>
        <translation>小齿轮 1</translation>
    </message>
    <message>
        <source>Gear 2</source>
        <translation>大齿轮 2</translation>
    </message>
    <message>
        <source>Teeth z</source>
        <translation>齿数 z</translation>
    </message>
    <message>
        <source>Module m</source>
        <translation>模数 m</translation>
    </message>
    <message>
        <source>Rack α, h*_a, c*</source>
        <translation>基本齿廓 α，h*_a，c*</translation>
    </message>
    <message>
        <source>Shift factor x</source>
        <translation>变位系数 x</translation>
    </message>
    <message>
        <source>Least shift x_min</source>
        <translation>最小变位系数 x_min</translation>
    </message>
    <message>
        <source>Reference diameter d</source>
        <translation>分度圆直径 d</translation>
    </message>
    <message>
        <source>Base diameter d_b</source>
        <translation>基圆直径 d_b</translation>
    </message>
    <message>
        <source>Tip diameter d_a</source>
        <translation>齿顶圆直径 d_a</translation>
    </message>
    <message>
        <source>Root diameter d_f</source>
        <translation>齿根圆直径 d_f</translation>
    </message>
    <message>
        <source>Working diameter d′</source>
        <translation>节圆直径 d′</translation>
    </message>
    <message>
        <source>Thickness s</source>
        <translation>分度圆齿厚 s</translation>
    </message>
    <message>
        <source>Space e</source>
        <translation>分度圆齿槽宽 e</translation>
    </message>
    <message>
        <source>Tip thickness s_a</source>
        <translation>齿顶厚 s_a</translation>
    </message>
    <message>
        <source>Centre distance a′ (a)</source>
        <translation>中心距 a′（a）</translation>
    </message>
    <message>
        <source>Working pressure angle α′</source>
        <translation>啮合角 α′</translation>
    </message>
    <message>
        <source>Centre shift y, reduction Δy</source>
        <translation>中心距变动系数 y，齿顶高降低系数 Δy</translation>
    </message>
    <message>
        <source>Base pitch p_b</source>
        <translation>基圆齿距 p_b</translation>
    </message>
    <message>
        <source>Lines of action N_1N_2, B_1B_2</source>
        <translation>理论啮合线 N_1N_2，实际啮合线 B_1B_2</translation>
    </message>
    <message>
        <source>Contact ratio ε</source>
        <translation>重合度 ε</translation>
    </message>
    <message>
        <source>Shifts</source>
        <translation>变位方式</translation>
    </message>
    <message>
        <source>given</source>
        <translation>给定</translation>
    </message>
    <message>
        <source>from a′</source>
        <translation>按中心距 a′</translation>
    </message>
    <message>
        <source>x_2 = −x_1</source>
        <translation>x_2 = −x_1</translation>
    </message>
    <message>
        <source>positive pair</source>
        <translation>正传动</translation>
    </message>
    <message>
        <source>No undercut</source>
        <translation>不根切</translation>
    </message>
    <message>
        <source>Tip s_a ≥ {k}</source>
        <translation>齿顶厚 s_a ≥ {k}</translation>
    </message>
    <message>
        <source>ε ≥ {k}</source>
        <translation>ε ≥ {k}</translation>
    </message>
    <message>
        <source>No root interference</source>
        <translation>齿根无干涉</translation>
    </message>
    <message>
        <source>ok</source>
        <translation>满足</translation>
    </message>
    <message>
        <source>FAILS</source>
        <translation>不满足</translation>
    </message>
    <message>
        <source>double contact</source>
        <translation>双齿啮合区</translation>
    </message>
    <message>
        <source>single contact</source>
        <translation>单齿啮合区</translation>
    </message>
    <message>
        <source>Actual line of action B_2B_1 and the contact zones, μ_l = {mu} m/mm ({scale})</source>
        <translation>实际啮合线 B_2B_1 与单、双齿啮合区，μ_l = {mu} m/mm（{scale}）</translation>
    </message>
</context>
<context>
    <name>DrawingSheetDialog</name>
    <message>
        <source>Export drawing sheet</source>
        <translation>导出图纸</translation>
    </message>
    <message>
        <source>Motion analysis</source>
        <translation>运动分析图</translation>
    </message>
    <message>
        <source>Kinetostatic analysis</source>
        <translation>动态静力分析图</translation>
    </message>
    <message>
        <source>Feed cam</source>
        <translation>进给凸轮</translation>
    </message>
    <message>
        <source>%1 r/min</source>
        <translation>%1 r/min</translation>
    </message>
    <message>
        <source>Paper:</source>
        <translation>图幅：</translation>
    </message>
    <message>
        <source>Content:</source>
        <translation>内容：</translation>
    </message>
    <message>
        <source>Crank speed:</source>
        <translation>曲柄转速：</translation>
    </message>
    <message>
        <source>Positions:</source>
        <translation>位置数：</translation>
    </message>
    <message>
        <source>Polygons at φ (working stroke):</source>
        <translation>多边形位置 φ（工作行程）：</translation>
    </message>
    <message>
        <source>Polygons at φ (return stroke):</source>
        <translation>多边形位置 φ（回程）：</translation>
    </message>
    <message>
        <source>Design name:</source>
        <translation>设计名称：</translation>
    </message>
    <message>
        <source>School:</source>
        <translation>学校：</translation>
    </message>
    <message>
        <source>Student:</source>
        <translation>学生：</translation>
    </message>
    <message>
        <source>Student number:</source>
        <translation>学号：</translation>
    </message>
    <message>
        <source>Class:</source>
        <translation>班级：</translation>
    </message>
    <message>
        <source>Date:</source>
        <translation>日期：</translation>
    </message>
    <message>
        <source>Supervisor:</source>
        <translation>指导教师：</translation>
    </message>
    <message>
        <source>Gear meshing</source>
        <translation>齿轮啮合图</translation>
    </message>
    <message>
        <source>The design's gear pair is not valid: %1</source>
        <translation>设计的齿轮副无效：%1</translation>
    </message>
    <message>
        <source>The design has no gear pair: open a design file with one (its "gear" object) to draw the meshing sheet.</source>
        <translation>该设计没有齿轮副：请打开含齿轮副（其 "gear" 对象）的设计文件，再绘制齿轮啮合图。</translation>
    </message>
    <message>
        <source>The sheet cannot be drawn: %1</source>
        <translation>无法绘制图纸：%1</translation>
    </message>
    <message>
        <source>No font with Chinese characters is installed: install one (on Debian/Ubuntu: fonts-noto-cjk) or switch the language to English.</source>
        <translation>未安装含中文字形的字体：请安装一个（Debian/Ubuntu 上为 fonts-noto-cjk），或把语言切换为英文。</translation>
    </message>
    <message>
        <source>The Cam tab has an error; the sheet shows its last valid cam.</source>
        <translation>凸轮选项卡中有错误；图纸显示最后一个有效的凸轮。</translation>
    </message>
    <message>
        <source>The Gear tab has an error; the sheet shows its last valid gear pair.</source>
        <translation>齿轮选项卡中有错误；图纸显示上一个有效的齿轮副。</translation>
    </message>
    <message>
        <source>PDF document (*.pdf)</source>
        <translation>PDF 文档 (*.pdf)</translation>
    </message>
    <message>
        <source>SVG image (*.svg)</source>
        <translation>SVG 图像 (*.svg)</translation>
    </message>
    <message>
        <source>DXF drawing (*.dxf)</source>
        <translation>DXF 图形 (*.dxf)</translation>
    </message>
    <message>
        <source>A drawing sheet is written as PDF (.pdf), SVG (.svg) or DXF (.dxf); %1 is none of them. Nothing was written.</source>
        <translation>图纸只能保存为 PDF (.pdf)、SVG (.svg) 或 DXF (.dxf)；%1 都不是。未写入任何文件。</translation>
    </message>
    <message>
        <source>Could not write %1: %2</source>
        <translation>无法写入 %1：%2</translation>
    </message>
    <message>
        <source>The sheet cannot be drawn: %1. Nothing was written.</source>
        <translation>无法绘制图纸：%1。未写入任何文件。</translation>
    </message>
    <message>
        <source>PDF document</source>
        <translation>PDF 文档</translation>
    </message>
    <message>
        <source>SVG image</source>
        <translation>SVG 图像</translation>
    </message>
    <message>
        <source>DXF drawing</source>
        <translation>DXF 图形</translation>
    </message>
    <message>
        <source>File type:</source>
        <translation>文件类型：</translation>
    </message>
    <message>
        <source>CAD texts:</source>
        <translation>CAD 文字：</translation>
    </message>
    <message>
        <source>Nothing was written.</source>
        <translation>未写入任何文件。</translation>
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
        <source>%1 — speeds %2 r/min</source>
        <translation>%1——转速 %2 r/min</translation>
    </message>
    <message>
        <source>pressure angle (°)</source>
        <translation>压力角 (°)</translation>
    </message>
    <message>
        <source>max |a| (m/s²)</source>
        <translation>最大 |a| (m/s²)</translation>
    </message>
    <message>
        <source>cutting speed (m/s)</source>
        <translation>切削速度 (m/s)</translation>
    </message>
    <message>
        <source>return speed (m/s)</source>
        <translation>回程速度 (m/s)</translation>
    </message>
    <message>
        <source>peak torque (N·m)</source>
        <translation>最大驱动力矩 (N·m)</translation>
    </message>
    <message>
        <source>J_F (kg·m²)</source>
        <translation>J_F (kg·m²)</translation>
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
        <source>The objective, %1, does not depend on %2: it changes by less than %3 of its value over the range.</source>
        <translation>优化目标“%1”与 %2 无关：在整个范围内其变化小于其值的 %3。</translation>
    </message>
    <message>
        <source>The best design found, %1 %2, is not better than the design before, %3 %2, by more than %4 of its value.</source>
        <translation>找到的最优设计为 %1 %2，比原设计的 %3 %2 改善不超过其值的 %4。</translation>
    </message>
    <message>
        <source>No better design within these bounds; the design is kept.</source>
        <translation>在这些范围内没有更好的设计；保留原设计。</translation>
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
        <source>Let Optimize change this parameter. K and H are your requirements: they stay fixed unless you tick this.</source>
        <translation>允许优化改变此参数。K 和 H 是您的设计要求：除非勾选此项，否则保持不变。</translation>
    </message>
    <message>
        <source>Undo proposal</source>
        <translation>撤销建议</translation>
    </message>
    <message>
        <source>Back to the design before Optimize (Edit › Undo does the same)</source>
        <translation>回到优化之前的设计（编辑 › 撤销 效果相同）</translation>
    </message>
    <message>
        <source>Choose two different parameters.</source>
        <translation>请选择两个不同的参数。</translation>
    </message>
    <message>
        <source>Give each axis a range with two different ends.</source>
        <translation>请为每个轴给出两个不同的端值。</translation>
    </message>
    <message>
        <source>Computing %1 designs…</source>
        <translation>正在计算 %1 个设计…</translation>
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
        <source>Proposal: %1 %2 at %3 (the design before: %4), loaded into the form; Undo proposal goes back.</source>
        <translation>建议：%3 时为 %1 %2（原设计：%4），已载入表单；点击“撤销建议”可返回。</translation>
    </message>
    <message>
        <source>%1 is at the lower end of its range: the best design may lie below it; widen the range.</source>
        <translation>%1 位于其范围的下限：最优设计可能在范围之外，请扩大范围。</translation>
    </message>
    <message>
        <source>%1 is at the upper end of its range: the best design may lie above it; widen the range.</source>
        <translation>%1 位于其范围的上限：最优设计可能在范围之外，请扩大范围。</translation>
    </message>
    <message>
        <source>not enough memory</source>
        <translation>内存不足</translation>
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
        <source>There is no map to export yet: press Compute map on the Explore tab first.</source>
        <translation>还没有可导出的分布图：请先在“设计空间”页按“计算分布图”。</translation>
    </message>
    <message>
        <source>Design-space map</source>
        <translation>设计空间图</translation>
    </message>
</context>
<context>
    <name>ForceLayer</name>
    <message>
        <source>{0:.1f} kN</source>
        <translation>{0:.1f} kN</translation>
    </message>
    <message>
        <source>{0:.0f} N</source>
        <translation>{0:.0f} N</translation>
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
    <name>ForcePlots</name>
    <message>
        <source>Shaper forces and torque</source>
        <translation>牛头刨床受力与力矩</translation>
    </message>
    <message>
        <source>cutting</source>
        <translation>切削区</translation>
    </message>
    <message>
        <source>mean torque</source>
        <translation>平均驱动力矩</translation>
    </message>
    <message>
        <source>Joint forces at {0}</source>
        <translation>{0} 时的运动副反力</translation>
    </message>
    <message>
        <source>r/min:</source>
        <translation>r/min：</translation>
    </message>
    <message>
        <source>Crank angle φ (°)</source>
        <translation>曲柄转角 φ (°)</translation>
    </message>
    <message>
        <source>φ = {0}°</source>
        <translation>φ = {0}°</translation>
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
        <source>guide</source>
        <translation>导路</translation>
    </message>
    <message>
        <source>Joint forces at:</source>
        <translation>运动副反力转速：</translation>
    </message>
    <message>
        <source>Crank speed whose joint forces are plotted</source>
        <translation>绘制运动副反力所用的曲柄转速</translation>
    </message>
</context>
<context>
    <name>GearForm</name>
    <message>
        <source>automatic (the rule)</source>
        <translation>自动（按规则）</translation>
    </message>
    <message>
        <source>shift factors x1, x2</source>
        <translation>变位系数 x1、x2</translation>
    </message>
    <message>
        <source>centre distance a′</source>
        <translation>中心距 a′</translation>
    </message>
    <message>
        <source>The pinion, on the motor side</source>
        <translation>小齿轮，在电动机一侧</translation>
    </message>
    <message>
        <source>The gear, on the crank's shaft</source>
        <translation>大齿轮，装在曲柄轴上</translation>
    </message>
    <message>
        <source>The last valid gear pair stays on screen.</source>
        <translation>屏幕上保留上一个有效的齿轮副。</translation>
    </message>
</context>
<context>
    <name>GearMessages</name>
    <message>
        <source>Teeth z1</source>
        <translation>齿数 z1</translation>
    </message>
    <message>
        <source>Teeth z2</source>
        <translation>齿数 z2</translation>
    </message>
    <message>
        <source>Module m</source>
        <translation>模数 m</translation>
    </message>
    <message>
        <source>Shift factor x1</source>
        <translation>变位系数 x1</translation>
    </message>
    <message>
        <source>Shift factor x2</source>
        <translation>变位系数 x2</translation>
    </message>
    <message>
        <source>Centre distance a′</source>
        <translation>中心距 a′</translation>
    </message>
    <message>
        <source>Pressure angle α</source>
        <translation>压力角 α</translation>
    </message>
    <message>
        <source>Addendum factor h*a</source>
        <translation>齿顶高系数 h*a</translation>
    </message>
    <message>
        <source>Clearance factor c*</source>
        <translation>顶隙系数 c*</translation>
    </message>
    <message>
        <source>Least tip thickness</source>
        <translation>最小齿顶厚</translation>
    </message>
    <message>
        <source>Least contact ratio</source>
        <translation>最小重合度</translation>
    </message>
    <message>
        <source>Shifts given as</source>
        <translation>变位给定方式</translation>
    </message>
    <message>
        <source>must be a whole number of teeth</source>
        <translation>齿数必须为整数</translation>
    </message>
    <message>
        <source>must be at most %1 at α = %2° and h*a = %3: the rack's tip rounding would not fit its tooth</source>
        <translation>在 α = %2°、h*a = %3 时不得大于 %1：齿条齿顶圆角放不进其齿顶</translation>
    </message>
    <message>
        <source>must be at least %1 and at most %2 teeth</source>
        <translation>必须不少于 %1 且不多于 %2 个齿</translation>
    </message>
    <message>
        <source>x1 + x2 is too negative: the gears would not mesh (α′ ≤ 0); raise x1 + x2 above %1</source>
        <translation>x1 + x2 过小：两齿轮无法啮合（α′ ≤ 0）；请使 x1 + x2 大于 %1</translation>
    </message>
    <message>
        <source>must be more than a cos α = %1 mm (the working pressure angle would be 0)</source>
        <translation>必须大于 a cos α = %1 mm（否则啮合角为 0）</translation>
    </message>
    <message>
        <source>needs x1 + x2 = %1, below the %2 that keeps both gears uncut; give at least %3 mm</source>
        <translation>需要 x1 + x2 = %1，小于两轮均不根切所需的 %2；请取不小于 %3 mm</translation>
    </message>
    <message>
        <source>x1 + x2 is too large: the addendum reduction leaves gear %1 no flank above its base circle; give %2 ≤ %3, for a tip of gear %1 at least %4 mm thick</source>
        <translation>x1 + x2 过大：齿顶高降低后齿轮 %1 在基圆以外没有齿廓；请取 %2 ≤ %3，使齿轮 %1 的齿顶厚不小于 %4 mm</translation>
    </message>
    <message>
        <source>x1 + x2 is too large: the addendum reduction Δy = %1 cuts both tips so far that the teeth never touch; give %2 ≤ %3</source>
        <translation>x1 + x2 过大：齿顶高降低系数 Δy = %1，两轮齿顶削减过多，轮齿不能接触；请取 %2 ≤ %3</translation>
    </message>
    <message>
        <source>x1 + x2 is too large: the addendum reduction Δy = %1 cuts both tips so far that the teeth never touch; give a′ ≤ %2 mm</source>
        <translation>x1 + x2 过大：齿顶高降低系数 Δy = %1，两轮齿顶削减过多，轮齿不能接触；请取 a′ ≤ %2 mm</translation>
    </message>
    <message>
        <source>x1 + x2 is too large: the addendum reduction Δy = %1 cuts both tips so far that the teeth never touch</source>
        <translation>x1 + x2 过大：齿顶高降低系数 Δy = %1，两轮齿顶削减过多，轮齿不能接触</translation>
    </message>
    <message>
        <source>makes the tip of gear %1 pointed (x = %2): give %3 ≤ %4, for a tip at least %5 mm thick</source>
        <translation>使齿轮 %1 齿顶变尖（x = %2）：请取 %3 ≤ %4，使齿顶厚不小于 %5 mm</translation>
    </message>
    <message>
        <source>makes the tip of gear %1 pointed (x = %2): give a′ ≤ %3 mm, for a tip at least %4 mm thick</source>
        <translation>使齿轮 %1 齿顶变尖（x = %2）：请取 a′ ≤ %3 mm，使齿顶厚不小于 %4 mm</translation>
    </message>
    <message>
        <source>too few teeth for the rule's shifts, which make the tip of gear %1 pointed (x = %2): give %3 ≥ %4, for a tip at least %5 mm thick</source>
        <translation>齿数过少，按规则取的变位使齿轮 %1 齿顶变尖（x = %2）：请取 %3 ≥ %4，使齿顶厚不小于 %5 mm</translation>
    </message>
    <message>
        <source>x1 + x2 is too large: the addendum reduction leaves gear %1 no flank above its base circle</source>
        <translation>x1 + x2 过大：齿顶高降低后齿轮 %1 在基圆以外没有齿廓</translation>
    </message>
    <message>
        <source>makes the tip of gear %1 pointed (x = %2): no smaller %3 found that gives a tip at least %4 mm thick; give gear %1 more teeth</source>
        <translation>使齿轮 %1 齿顶变尖（x = %2）：未找到能使齿顶厚不小于 %4 mm 的更小的 %3；请增加齿轮 %1 的齿数</translation>
    </message>
    <message>
        <source>makes the tip of gear %1 pointed (x = %2): no smaller centre distance found that gives a tip at least %3 mm thick; give gear %1 more teeth</source>
        <translation>使齿轮 %1 齿顶变尖（x = %2）：未找到能使齿顶厚不小于 %3 mm 的更小的中心距；请增加齿轮 %1 的齿数</translation>
    </message>
    <message>
        <source>no change of one shift or of a′ makes it pass: try other teeth</source>
        <translation>单独改变一个变位系数或 a′ 均不能使其合格：请改变齿数</translation>
    </message>
    <message>
        <source>too few teeth for the rule's shifts, which make the tip of gear %1 pointed (x = %2): give more teeth, or the shifts or the centre distance</source>
        <translation>齿数过少，按规则取的变位使齿轮 %1 齿顶变尖（x = %2）：请增加齿数，或直接给定变位系数或中心距</translation>
    </message>
    <message>
        <source>m = %1 mm is not a GB/T 1357 first-series module</source>
        <translation>m = %1 mm 不是 GB/T 1357 第一系列模数</translation>
    </message>
    <message>
        <source>Gear %1 not undercut: x%1 ≥ x%1min</source>
        <translation>齿轮 %1 不根切：x%1 ≥ x%1min</translation>
    </message>
    <message>
        <source>Gear %1 tip thick enough: sa%1 ≥ %2 mm</source>
        <translation>齿轮 %1 齿顶厚足够：sa%1 ≥ %2 mm</translation>
    </message>
    <message>
        <source>Contact ratio: ε ≥ %1</source>
        <translation>重合度：ε ≥ %1</translation>
    </message>
    <message>
        <source>No interference at the root of gear %1</source>
        <translation>齿轮 %1 齿根无干涉</translation>
    </message>
    <message>
        <source>raise %1</source>
        <translation>增大 %1</translation>
    </message>
    <message>
        <source>lower %1</source>
        <translation>减小 %1</translation>
    </message>
    <message>
        <source>a larger a′</source>
        <translation>增大 a′</translation>
    </message>
    <message>
        <source>a smaller a′</source>
        <translation>减小 a′</translation>
    </message>
    <message>
        <source>x1 + δ and x2 − δ at the same a′</source>
        <translation>a′ 不变，x1 增大 δ、x2 减小 δ</translation>
    </message>
    <message>
        <source>x1 − δ and x2 + δ at the same a′</source>
        <translation>a′ 不变，x1 减小 δ、x2 增大 δ</translation>
    </message>
    <message>
        <source>raise %1 to ≥ %2</source>
        <translation>将 %1 增大到 ≥ %2</translation>
    </message>
    <message>
        <source>lower %1 to ≤ %2</source>
        <translation>将 %1 减小到 ≤ %2</translation>
    </message>
    <message>
        <source>raise a′ to ≥ %2 mm</source>
        <translation>将 a′ 增大到 ≥ %2 mm</translation>
    </message>
    <message>
        <source>lower a′ to ≤ %2 mm</source>
        <translation>将 a′ 减小到 ≤ %2 mm</translation>
    </message>
    <message>
        <source>x1 = %2 and x2 = %3 (a′ about the same)</source>
        <translation>取 x1 = %2、x2 = %3（a′ 基本不变）</translation>
    </message>
    <message>
        <source>%1, %2</source>
        <translation>%1、%2</translation>
    </message>
    <message>
        <source>%1 (but then %2)</source>
        <translation>%1（但此时%2）</translation>
    </message>
    <message>
        <source>gear %1 is undercut</source>
        <translation>齿轮 %1 根切</translation>
    </message>
    <message>
        <source>raise x%1 to ≥ %2 (or give gear %1 more teeth)</source>
        <translation>将 x%1 增大到 ≥ %2（或增加齿轮 %1 的齿数）</translation>
    </message>
    <message>
        <source>the tip of gear %1 is too thin</source>
        <translation>齿轮 %1 的齿顶过薄</translation>
    </message>
    <message>
        <source>ε is too small</source>
        <translation>ε 过小</translation>
    </message>
    <message>
        <source>the tip of gear %2 digs into the root of gear %1</source>
        <translation>齿轮 %2 的齿顶与齿轮 %1 的齿根干涉</translation>
    </message>
    <message>
        <source>%1 or %2</source>
        <translation>%1，或%2</translation>
    </message>
    <message>
        <source>x1 and x2 given</source>
        <translation>给定 x1 和 x2</translation>
    </message>
    <message>
        <source>from the centre distance: the pinion's least uncut shift, the rest to the gear</source>
        <translation>由中心距求得：小齿轮取不根切的最小变位，其余归大齿轮</translation>
    </message>
    <message>
        <source>rule: z1 + z2 ≥ 2 zmin, the pinion's least uncut shift and x2 = −x1</source>
        <translation>规则：z1 + z2 ≥ 2 zmin，小齿轮取不根切的最小变位，x2 = −x1</translation>
    </message>
    <message>
        <source>rule: z1 + z2 &lt; 2 zmin, the least positive pair at a′ rounded up to a step of about m/10</source>
        <translation>规则：z1 + z2 &lt; 2 zmin，取最小的正传动，a′ 按约 m/10 的步长向上圆整</translation>
    </message>
</context>
<context>
    <name>GearModel</name>
    <message>
        <source>edit gear pair</source>
        <translation>编辑齿轮副</translation>
    </message>
    <message>
        <source>This design's gear pair cannot be made: no pair is shown.</source>
        <translation>此设计的齿轮副无法求出：不显示齿轮副。</translation>
    </message>
</context>
<context>
    <name>GearPairView</name>
    <message>
        <source>crank φ = %1°: gear z2 turned %1° clockwise, pinion z1 %2° counter-clockwise (i = %3)</source>
        <translation>曲柄 φ = %1°：大齿轮 z2 顺时针转过 %1°，小齿轮 z1 逆时针转过 %2°（i = %3）</translation>
    </message>
</context>
<context>
    <name>GearResults</name>
    <message>
        <source>Teeth</source>
        <translation>齿数</translation>
    </message>
    <message>
        <source>Shift factor</source>
        <translation>变位系数</translation>
    </message>
    <message>
        <source>Least shift factor without undercut</source>
        <translation>不根切的最小变位系数</translation>
    </message>
    <message>
        <source>Reference diameter</source>
        <translation>分度圆直径</translation>
    </message>
    <message>
        <source>Base diameter</source>
        <translation>基圆直径</translation>
    </message>
    <message>
        <source>Tip diameter</source>
        <translation>齿顶圆直径</translation>
    </message>
    <message>
        <source>Root diameter</source>
        <translation>齿根圆直径</translation>
    </message>
    <message>
        <source>Working pitch diameter</source>
        <translation>节圆直径</translation>
    </message>
    <message>
        <source>Tooth thickness on the reference circle</source>
        <translation>分度圆齿厚</translation>
    </message>
    <message>
        <source>Space width on the reference circle</source>
        <translation>分度圆齿槽宽</translation>
    </message>
    <message>
        <source>Tip thickness</source>
        <translation>齿顶厚</translation>
    </message>
    <message>
        <source>Undercut</source>
        <translation>根切</translation>
    </message>
    <message>
        <source>Undercut by the rack (x &lt; xmin)</source>
        <translation>被齿条刀具根切（x &lt; xmin）</translation>
    </message>
    <message>
        <source>Centre distance</source>
        <translation>中心距</translation>
    </message>
    <message>
        <source>Standard centre distance</source>
        <translation>标准中心距</translation>
    </message>
    <message>
        <source>Working pressure angle</source>
        <translation>啮合角</translation>
    </message>
    <message>
        <source>Centre distance shift factor</source>
        <translation>中心距变动系数</translation>
    </message>
    <message>
        <source>Addendum reduction factor</source>
        <translation>齿顶高降低系数</translation>
    </message>
    <message>
        <source>Ratio</source>
        <translation>传动比</translation>
    </message>
    <message>
        <source>Base pitch</source>
        <translation>基圆齿距</translation>
    </message>
    <message>
        <source>Line of action between the limit points</source>
        <translation>理论啮合线</translation>
    </message>
    <message>
        <source>Actual line of action</source>
        <translation>实际啮合线</translation>
    </message>
    <message>
        <source>Contact ratio</source>
        <translation>重合度</translation>
    </message>
    <message>
        <source>ok</source>
        <translation>满足</translation>
    </message>
    <message>
        <source>fails: %1</source>
        <translation>不满足：%1</translation>
    </message>
    <message>
        <source>Pinion 1</source>
        <translation>小齿轮 1</translation>
    </message>
    <message>
        <source>Gear 2</source>
        <translation>大齿轮 2</translation>
    </message>
    <message>
        <source>Pair</source>
        <translation>齿轮副</translation>
    </message>
    <message>
        <source>Shifts: %1</source>
        <translation>变位：%1</translation>
    </message>
</context>
<context>
    <name>GearTab</name>
    <message>
        <source>Close-up of the line of action</source>
        <translation>放大显示啮合线附近</translation>
    </message>
    <message>
        <source>CSV…</source>
        <translation>CSV…</translation>
    </message>
    <message>
        <source>Meshing sheet…</source>
        <translation>啮合图…</translation>
    </message>
    <message>
        <source>The meshing drawing (sheet 4/4) as PDF, SVG or DXF</source>
        <translation>齿轮啮合图（第 4/4 张）导出为 PDF、SVG 或 DXF</translation>
    </message>
    <message>
        <source>%1 is not a PDF, SVG or DXF file name</source>
        <translation>%1 不是 PDF、SVG 或 DXF 文件名</translation>
    </message>
    <message>
        <source>CSV table (*.csv)</source>
        <translation>CSV 表格 (*.csv)</translation>
    </message>
    <message>
        <source>PDF document (*.pdf)</source>
        <translation>PDF 文档 (*.pdf)</translation>
    </message>
    <message>
        <source>SVG image (*.svg)</source>
        <translation>SVG 图像 (*.svg)</translation>
    </message>
    <message>
        <source>Export the gear pair</source>
        <translation>导出齿轮副</translation>
    </message>
</context>
<context>
    <name>ImageExport</name>
    <message>
        <source>“.{0}” is not an image type this program writes; use .png or .svg</source>
        <translation>本程序不能写出 “.{0}” 类型的图像；请使用 .png 或 .svg</translation>
    </message>
    <message>
        <source>the name has no image type; end it in .png or .svg</source>
        <translation>文件名没有图像类型；请以 .png 或 .svg 结尾</translation>
    </message>
    <message>
        <source>Cannot export to {0}: {1}</source>
        <translation>无法导出到 {0}：{1}</translation>
    </message>
    <message>
        <source>the folder {0} does not exist</source>
        <translation>文件夹 {0} 不存在</translation>
    </message>
    <message>
        <source>the folder {0} is not writable</source>
        <translation>文件夹 {0} 不可写</translation>
    </message>
    <message>
        <source>{0} is a folder</source>
        <translation>{0} 是一个文件夹</translation>
    </message>
    <message>
        <source>Qt could not encode the image as {0}</source>
        <translation>Qt 无法将图像编码为 {0}</translation>
    </message>
    <message>
        <source>could not write {0}: {1}</source>
        <translation>无法写入 {0}：{1}</translation>
    </message>
</context>
<context>
    <name>InputsPane</name>
    <message>
        <source>Design</source>
        <translation>设计参数</translation>
    </message>
    <message>
        <source>Loads</source>
        <translation>载荷</translation>
    </message>
    <message>
        <source>Dimensions or L1, K, H; mechanism; crank speeds</source>
        <translation>尺寸或 L1、K、H；机构；曲柄转速</translation>
    </message>
    <message>
        <source>Masses, cutting force and flywheel requirement (for the Forces tab and the forces and flywheel results)</source>
        <translation>质量、切削力与飞轮要求（用于力分析选项卡及力与飞轮结果）</translation>
    </message>
</context>
<context>
    <name>LibraryActions</name>
    <message>
        <source>Save “%1”</source>
        <translation>保存“%1”</translation>
    </message>
    <message>
        <source>Rename “%1”</source>
        <translation>重命名“%1”</translation>
    </message>
    <message>
        <source>Duplicate “%1”</source>
        <translation>复制“%1”</translation>
    </message>
    <message>
        <source>Delete %1 design(s)</source>
        <translation>删除 %1 个设计</translation>
    </message>
    <message>
        <source>Import %1 design(s)</source>
        <translation>导入 %1 个设计</translation>
    </message>
    <message>
        <source>No library is open.</source>
        <translation>未打开设计库。</translation>
    </message>
    <message>
        <source>These designs were not exported:</source>
        <translation>以下设计未导出：</translation>
    </message>
    <message>
        <source>Could not write %1: %2</source>
        <translation>无法写入 %1：%2</translation>
    </message>
    <message>
        <source>Could not open the design: %1</source>
        <translation>无法打开设计：%1</translation>
    </message>
    <message>
        <source>That name is already in the library; choose another.</source>
        <translation>设计库中已有该名称，请另选一个。</translation>
    </message>
    <message>
        <source>A name must not be empty, longer than 200 characters or contain line breaks.</source>
        <translation>名称不能为空，不能超过 200 个字符，也不能包含换行。</translation>
    </message>
    <message>
        <source>Tags are separated by commas; each at most 64 characters.</source>
        <translation>标签之间用逗号分隔；每个标签最多 64 个字符。</translation>
    </message>
    <message>
        <source>That design is no longer in the library (another program may have changed it).</source>
        <translation>该设计已不在设计库中（可能被另一个程序修改）。</translation>
    </message>
    <message>
        <source>The library is busy: another program is writing to it. Try again.</source>
        <translation>设计库正忙：另一个程序正在写入。请稍后重试。</translation>
    </message>
    <message>
        <source>The library %1 is damaged and cannot be opened. It was left unchanged.</source>
        <translation>设计库 %1 已损坏，无法打开。文件未作任何改动。</translation>
    </message>
    <message>
        <source>The library %1 was written by a newer version of Shaper Designer. It was left unchanged; update Shaper Designer to use it.</source>
        <translation>设计库 %1 由更新版本的 Shaper Designer 写入。文件未作任何改动；请升级 Shaper Designer 后再使用。</translation>
    </message>
    <message>
        <source>%1 is not a Shaper Designer library. It was left unchanged.</source>
        <translation>%1 不是 Shaper Designer 设计库。文件未作任何改动。</translation>
    </message>
    <message>
        <source>The library %1 holds what another program added (%2), which Shaper Designer never makes and will not run. It was left unchanged.</source>
        <translation>设计库 %1 含有其他程序加入的对象（%2），Shaper Designer 从不创建也不会执行它们。文件未作任何改动。</translation>
    </message>
    <message>
        <source>This design is damaged and cannot be opened; the rest of the library can be used. (%1)</source>
        <translation>此设计已损坏，无法打开；设计库中的其他设计仍可使用。（%1）</translation>
    </message>
    <message>
        <source>The library %1 can only be read (the file or its folder cannot be written); nothing was changed.</source>
        <translation>设计库 %1 只能读取（文件或其所在文件夹不可写入），未作任何更改。</translation>
    </message>
    <message>
        <source>Could not use the library: %1</source>
        <translation>无法使用设计库：%1</translation>
    </message>
</context>
<context>
    <name>LibraryDialogs</name>
    <message>
        <source>Design library</source>
        <translation>设计库</translation>
    </message>
    <message>
        <source>You can keep a copy of the file aside (it is copied byte for byte), then choose or create another library.</source>
        <translation>可以先把该文件另存一份副本（逐字节复制），再选择或新建另一个设计库。</translation>
    </message>
    <message>
        <source>Copy it aside</source>
        <translation>另存副本</translation>
    </message>
    <message>
        <source>Choose another library…</source>
        <translation>选择其他设计库…</translation>
    </message>
</context>
<context>
    <name>LibraryPane</name>
    <message>
        <source>No library is open.</source>
        <translation>未打开设计库。</translation>
    </message>
    <message>
        <source>%1 (read-only: %2)</source>
        <translation>%1（只读：%2）</translation>
    </message>
    <message>
        <source>Undo: %1</source>
        <translation>撤销：%1</translation>
    </message>
    <message>
        <source>Redo: %1</source>
        <translation>重做：%1</translation>
    </message>
    <message>
        <source>Design library</source>
        <translation>设计库</translation>
    </message>
    <message>
        <source>“%1” is already in the library. Replace it?</source>
        <translation>设计库中已有“%1”。是否替换？</translation>
    </message>
    <message>
        <source>The design on screen has unsaved changes. Open “%1” anyway?</source>
        <translation>当前设计有未保存的修改。仍要打开“%1”吗？</translation>
    </message>
    <message>
        <source>Rename design</source>
        <translation>重命名设计</translation>
    </message>
    <message>
        <source>New name:</source>
        <translation>新名称：</translation>
    </message>
    <message>
        <source>Import design files</source>
        <translation>导入设计文件</translation>
    </message>
    <message>
        <source>Shaper designs (*.shaper.json *.json);;All files (*)</source>
        <translation>牛头刨床设计 (*.shaper.json *.json);;所有文件 (*)</translation>
    </message>
    <message>
        <source>Import a folder of designs</source>
        <translation>导入设计文件夹</translation>
    </message>
    <message>
        <source>Imported %1 design(s).</source>
        <translation>已导入 %1 个设计。</translation>
    </message>
    <message>
        <source>These files were not imported:</source>
        <translation>以下文件未导入：</translation>
    </message>
    <message>
        <source>Export design</source>
        <translation>导出设计</translation>
    </message>
    <message>
        <source>Shaper designs (*.shaper.json *.json)</source>
        <translation>牛头刨床设计 (*.shaper.json *.json)</translation>
    </message>
    <message>
        <source>Export all designs to a folder</source>
        <translation>将全部设计导出到文件夹</translation>
    </message>
    <message>
        <source>Exported the library to %1</source>
        <translation>设计库已导出到 %1</translation>
    </message>
    <message>
        <source>Open or create a design library</source>
        <translation>打开或新建设计库</translation>
    </message>
    <message>
        <source>Design libraries (*.sqlite);;All files (*)</source>
        <translation>设计库 (*.sqlite);;所有文件 (*)</translation>
    </message>
    <message>
        <source>Type a crank speed in r/min.</source>
        <translation>请输入曲柄转速 (r/min)。</translation>
    </message>
    <message>
        <source>Filter not understood; write conditions such as K&gt;=1.4, variant=rod, name~cut.</source>
        <translation>无法识别筛选条件；请写成 K&gt;=1.4, variant=rod, name~cut 这样的形式。</translation>
    </message>
    <message>
        <source>A copy was saved as %1</source>
        <translation>副本已保存为 %1</translation>
    </message>
    <message>
        <source>Save current…</source>
        <translation>保存当前设计…</translation>
    </message>
    <message>
        <source>Save the design on screen to the library</source>
        <translation>将当前设计保存到设计库</translation>
    </message>
    <message>
        <source>Open</source>
        <translation>打开</translation>
    </message>
    <message>
        <source>Open the selected design (double-click works too)</source>
        <translation>打开选中的设计（也可双击）</translation>
    </message>
    <message>
        <source>Compare</source>
        <translation>比较</translation>
    </message>
    <message>
        <source>Compare the 2 to 6 selected designs</source>
        <translation>比较选中的 2 至 6 个设计</translation>
    </message>
    <message>
        <source>Rename…</source>
        <translation>重命名…</translation>
    </message>
    <message>
        <source>Duplicate</source>
        <translation>复制</translation>
    </message>
    <message>
        <source>Delete</source>
        <translation>删除</translation>
    </message>
    <message>
        <source>Delete the selected designs (undoable)</source>
        <translation>删除选中的设计（可撤销）</translation>
    </message>
    <message>
        <source>Import…</source>
        <translation>导入…</translation>
    </message>
    <message>
        <source>Add design files to the library</source>
        <translation>将设计文件加入设计库</translation>
    </message>
    <message>
        <source>Import folder…</source>
        <translation>导入文件夹…</translation>
    </message>
    <message>
        <source>Import</source>
        <translation>导入</translation>
    </message>
    <message>
        <source>Add design files, or every design file of a folder, to the library</source>
        <translation>将设计文件或一个文件夹中的全部设计文件加入设计库</translation>
    </message>
    <message>
        <source>Export</source>
        <translation>导出</translation>
    </message>
    <message>
        <source>Write the selected design, or every design, as design files</source>
        <translation>将选中的设计或全部设计写成设计文件</translation>
    </message>
    <message>
        <source>Add every design file of a folder</source>
        <translation>加入文件夹中的全部设计文件</translation>
    </message>
    <message>
        <source>Export…</source>
        <translation>导出…</translation>
    </message>
    <message>
        <source>Write the selected design as a design file</source>
        <translation>将选中的设计写成设计文件</translation>
    </message>
    <message>
        <source>Export all…</source>
        <translation>全部导出…</translation>
    </message>
    <message>
        <source>Write every design into a folder</source>
        <translation>将全部设计写入一个文件夹</translation>
    </message>
    <message>
        <source>Undo</source>
        <translation>撤销</translation>
    </message>
    <message>
        <source>Redo</source>
        <translation>重做</translation>
    </message>
    <message>
        <source>Other library…</source>
        <translation>其他设计库…</translation>
    </message>
    <message>
        <source>Search name, notes, tags</source>
        <translation>搜索名称、备注、标签</translation>
    </message>
    <message>
        <source>Filter, e.g. K&gt;=1.4, variant=rod, a_max&lt;5</source>
        <translation>筛选，例如 K&gt;=1.4, 方案=连杆, 最大 |a|&lt;5</translation>
    </message>
    <message>
        <source>Figures at each design's first speed</source>
        <translation>按各设计的第一个转速</translation>
    </message>
    <message>
        <source>Crank speed of the speed-dependent columns, r/min</source>
        <translation>与转速有关的各列所用的曲柄转速，r/min</translation>
    </message>
</context>
<context>
    <name>LibraryTableModel</name>
    <message>
        <source>This design is damaged: %1. 'shaper library check' lists every damaged design.</source>
        <translation>此设计已损坏：%1。“shaper library check”会列出所有损坏的设计。</translation>
    </message>
    <message>
        <source>%1 (damaged)</source>
        <translation>%1（已损坏）</translation>
    </message>
</context>
<context>
    <name>LoadsForm</name>
    <message>
        <source>L3/2 = {0}</source>
        <translation>L3/2 = {0}</translation>
    </message>
    <message>
        <source>H = {0}</source>
        <translation>H = {0}</translation>
    </message>
    <message>
        <source>none</source>
        <translation>无</translation>
    </message>
    <message>
        <source>Mass m4</source>
        <translation>质量 m4</translation>
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
        <source>Inertia J_S4</source>
        <translation>转动惯量 J_S4</translation>
    </message>
    <message>
        <source>Moment of inertia of the lever about its centre of mass, kg·m²</source>
        <translation>导杆绕其质心的转动惯量，kg·m²</translation>
    </message>
    <message>
        <source>Mass m6</source>
        <translation>质量 m6</translation>
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
        <source>Rod mass m5</source>
        <translation>连杆质量 m5</translation>
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
        <translation>切削力 P</translation>
    </message>
    <message>
        <source>Cutting resistance on the tool, against the cut, N</source>
        <translation>作用于刨刀、与切削方向相反的切削力，N</translation>
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
        <source>Load given as</source>
        <translation>载荷给定为</translation>
    </message>
    <message>
        <source>The lever's load as a mass in kg, or as the task book states it, a weight G4 in N (mass = G4/9.81)</source>
        <translation>导杆的载荷：以质量 kg 给出，或如任务书以重量 G4（N）给出（质量 = G4/9.81）</translation>
    </message>
    <message>
        <source>Weight G4</source>
        <translation>重量 G4</translation>
    </message>
    <message>
        <source>Weight of the slotted lever O4B, N, as the task book states it</source>
        <translation>导杆 O4B 的重量，N，同任务书</translation>
    </message>
    <message>
        <source>The ram's load as a mass in kg, or as the task book states it, a weight G6 in N (mass = G6/9.81)</source>
        <translation>滑枕的载荷：以质量 kg 给出，或如任务书以重量 G6（N）给出（质量 = G6/9.81）</translation>
    </message>
    <message>
        <source>Weight G6</source>
        <translation>重量 G6</translation>
    </message>
    <message>
        <source>Weight of the ram with the tool, N, as the task book states it</source>
        <translation>滑枕连同刀具的重量，N，同任务书</translation>
    </message>
    <message>
        <source>Guide length</source>
        <translation>导路长度</translation>
    </message>
    <message>
        <source>Length of the ram's guide (the column's ways), centred on the ram's mid-travel, mm; leave empty for the stroke H. Where the guide's reaction falls outside it, the ram tilts and bears on the guide's two ends</source>
        <translation>滑枕导路（床身上的导路）的长度，以滑枕行程中点为中心，mm；留空则取行程 H。导路反力的合力落在导路之外时，滑枕倾斜，支承于导路两端</translation>
    </message>
    <message>
        <source>Rotating parts</source>
        <translation>其他转动构件</translation>
    </message>
    <message>
        <source>Other rotating parts (crank shaft, gears, motor) for the flywheel, each J:ratio, J in kg·m² and its speed over the crank's, separated by ';' (e.g. 0.5:1; 0.02:15); J:gear takes z2/z1 of the Gear tab's pair, for the pinion shaft. The flywheel needed is J_F − Σ J·ratio²</source>
        <translation>飞轮计算中的其他转动构件（曲柄轴、齿轮、电动机），每个写作 J:传动比，J 单位 kg·m²，传动比为其转速与曲柄转速之比，以“;”分隔（如 0.5:1; 0.02:15）；J:gear 取齿轮页齿轮副的 z2/z1，用于小齿轮轴。所需飞轮为 J_F − Σ J·传动比²</translation>
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
        <source>mass, kg</source>
        <translation>质量，kg</translation>
    </message>
    <message>
        <source>weight, N</source>
        <translation>重量，N</translation>
    </message>
    <message>
        <source>include weights</source>
        <translation>计入重力</translation>
    </message>
    <message>
        <source>The last valid results stay on screen.</source>
        <translation>屏幕上保留最后一次有效结果。</translation>
    </message>
</context>
<context>
    <name>MainWindow</name>
    <message>
        <source>Show &amp;library</source>
        <translation>显示设计库(&amp;L)</translation>
    </message>
    <message>
        <source>&amp;Save design to library…</source>
        <translation>保存设计到设计库(&amp;S)…</translation>
    </message>
    <message>
        <source>&amp;Compare designs</source>
        <translation>比较设计(&amp;C)</translation>
    </message>
    <message>
        <source>Compare</source>
        <translation>比较</translation>
    </message>
    <message>
        <source>Undo</source>
        <translation>撤销</translation>
    </message>
    <message>
        <source>Redo</source>
        <translation>重做</translation>
    </message>
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
        <source>Export scheme as D&amp;XF…</source>
        <translation>导出机构简图为 DXF(&amp;X)…</translation>
    </message>
    <message>
        <source>The mechanism at the current crank angle for CAD: 1:1 in mm, with its dimensions</source>
        <translation>当前曲柄转角下的机构，供 CAD 使用：1:1，单位 mm，带尺寸标注</translation>
    </message>
    <message>
        <source>Export r&amp;eport (PDF/HTML)…</source>
        <translation>导出设计说明书(&amp;E)（PDF/HTML）…</translation>
    </message>
    <message>
        <source>The design report: dimensions, positions table, polygons, forces, flywheel</source>
        <translation>设计说明书：尺寸、位置表、矢量多边形、力分析、飞轮</translation>
    </message>
    <message>
        <source>Export &amp;drawing sheet (PDF/SVG/DXF)…</source>
        <translation>导出图纸(&amp;D)（PDF/SVG/DXF）…</translation>
    </message>
    <message>
        <source>The course design's drawing sheet on A0–A3 paper, with a preview</source>
        <translation>课程设计图纸，A0–A3 图幅，带预览</translation>
    </message>
    <message>
        <source>Export course desi&amp;gn…</source>
        <translation>导出课程设计(&amp;G)…</translation>
    </message>
    <message>
        <source>The report and every drawing sheet into one folder, as shaper course writes them</source>
        <translation>将设计说明书和全部图纸写入一个文件夹，与 shaper course 命令写出的相同</translation>
    </message>
    <message>
        <source>C&amp;lass course design…</source>
        <translation>全班课程设计(&amp;L)…</translation>
    </message>
    <message>
        <source>A whole class from a table of data sets: each student's folder, the task sheets and the answer key, as shaper class writes them</source>
        <translation>由数据表生成全班的课程设计：每名学生的文件夹、任务书和参考答案，与 shaper class 相同</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>退出(&amp;Q)</translation>
    </message>
    <message>
        <source>&amp;Go to Crank Angle…</source>
        <translation>转到曲柄转角(&amp;G)…</translation>
    </message>
    <message>
        <source>Move the mechanism to a crank angle you type</source>
        <translation>将机构移动到输入的曲柄转角</translation>
    </message>
    <message>
        <source>Fi&amp;t plots</source>
        <translation>曲线全部显示(&amp;T)</translation>
    </message>
    <message>
        <source>Show the whole cycle in the plots of the current tab</source>
        <translation>在当前选项卡的曲线中显示整个运动循环</translation>
    </message>
    <message>
        <source>&amp;Reset layout</source>
        <translation>恢复默认布局(&amp;R)</translation>
    </message>
    <message>
        <source>Put every pane back in its place for this window size</source>
        <translation>按当前窗口大小把各面板放回默认位置</translation>
    </message>
    <message>
        <source>&amp;About</source>
        <translation>关于(&amp;A)</translation>
    </message>
    <message>
        <source>User &amp;guide</source>
        <translation>使用指南(&amp;G)</translation>
    </message>
    <message>
        <source>Conventions, method, glossary and command line</source>
        <translation>约定、方法、术语表和命令行</translation>
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
        <source>Positions</source>
        <translation>位置</translation>
    </message>
    <message>
        <source>Explore</source>
        <translation>设计空间</translation>
    </message>
    <message>
        <source>Cam</source>
        <translation>凸轮</translation>
    </message>
    <message>
        <source>Gear</source>
        <translation>齿轮</translation>
    </message>
    <message>
        <source>&amp;Undo %1</source>
        <translation>撤销(&amp;U) %1</translation>
    </message>
    <message>
        <source>&amp;Redo %1</source>
        <translation>重做(&amp;R) %1</translation>
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
        <source>the folder %1 does not exist</source>
        <translation>文件夹 %1 不存在</translation>
    </message>
    <message>
        <source>nothing was written</source>
        <translation>未写入任何内容</translation>
    </message>
    <message>
        <source>Could not export the image to %1: %2</source>
        <translation>无法将图像导出到 %1：%2</translation>
    </message>
    <message>
        <source>Go to crank angle</source>
        <translation>转到曲柄转角</translation>
    </message>
    <message>
        <source>Crank angle φ (0–360°):</source>
        <translation>曲柄转角 φ（0–360°）：</translation>
    </message>
    <message>
        <source>About Shaper Designer</source>
        <translation>关于 牛头刨床机构设计</translation>
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
        <source>&amp;Edit</source>
        <translation>编辑(&amp;E)</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>视图(&amp;V)</translation>
    </message>
    <message>
        <source>&amp;Panes</source>
        <translation>面板(&amp;P)</translation>
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
        <source>&amp;Library</source>
        <translation>设计库(&amp;L)</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>帮助(&amp;H)</translation>
    </message>
    <message>
        <source>Main toolbar</source>
        <translation>主工具栏</translation>
    </message>
    <message>
        <source>&amp;Toolbar</source>
        <translation>工具栏(&amp;T)</translation>
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
        <source>Synthesized dimensions</source>
        <translation>综合所得尺寸</translation>
    </message>
    <message>
        <source>Measured cycle</source>
        <translation>实测运动循环</translation>
    </message>
    <message>
        <source>Flywheel needed J_F − J_c, kg·m²</source>
        <translation>所需飞轮 J_F − J_c，kg·m²</translation>
    </message>
    <message>
        <source>J_F − J_c − J_e (net), kg·m²</source>
        <translation>飞轮 J_F − J_c − J_e（净），kg·m²</translation>
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
        <source>Per crank speed</source>
        <translation>各曲柄转速</translation>
    </message>
    <message>
        <source>Constant crank speed; loads as set in the Loads inputs</source>
        <translation>曲柄匀速转动；载荷取自“载荷”输入</translation>
    </message>
    <message>
        <source>Dimensions</source>
        <translation>机构尺寸</translation>
    </message>
    <message>
        <source>%1, %2</source>
        <translation>%1，%2</translation>
    </message>
    <message>
        <source>Value</source>
        <translation>数值</translation>
    </message>
    <message>
        <source>%1 r/min</source>
        <translation>%1 r/min</translation>
    </message>
</context>
<context>
    <name>PartTab</name>
    <message>
        <source>Nothing was exported.</source>
        <translation>未导出任何内容。</translation>
    </message>
    <message>
        <source>%1 Export it instead?</source>
        <translation>%1仍要导出它吗？</translation>
    </message>
</context>
<context>
    <name>PlotStack</name>
    <message>
        <source>Fit all</source>
        <translation>全部显示</translation>
    </message>
    <message>
        <source>Show the whole cycle again (or double-click a plot)</source>
        <translation>重新显示整个周期（或双击曲线图）</translation>
    </message>
    <message>
        <source>Drag zooms to a box</source>
        <translation>拖动框选放大</translation>
    </message>
    <message>
        <source>Left drag: zoom to a box; off: pan</source>
        <translation>左键拖动：框选放大；关闭时：平移</translation>
    </message>
    <message>
        <source>Wheel: zoom x; wheel over an axis: zoom y; drag: zoom to a box; double-click: fit; click: set the crank angle; right click: menu</source>
        <translation>滚轮：缩放 x；在坐标轴上滚动：缩放 y；拖动：框选放大；双击：全部显示；单击：设置曲柄转角；右键：菜单</translation>
    </message>
    <message>
        <source>Values under the mouse, or at the cursor while the crank moves; click a plot to move the mechanism to that crank position</source>
        <translation>鼠标处的数值，曲柄转动时为光标处的数值；单击曲线图可将机构移到该曲柄位置</translation>
    </message>
    <message>
        <source>cursor {0}</source>
        <translation>光标 {0}</translation>
    </message>
</context>
<context>
    <name>PlotsWidget</name>
    <message>
        <source>Shaper motion diagrams</source>
        <translation>牛头刨床运动线图</translation>
    </message>
    <message>
        <source>r/min:</source>
        <translation>r/min：</translation>
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
        <source>every speed</source>
        <translation>各转速相同</translation>
    </message>
    <message>
        <source>return stroke</source>
        <translation>回程</translation>
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
        <source>φ = {0}°</source>
        <translation>φ = {0}°</translation>
    </message>
    <message>
        <source>t = {0} s</source>
        <translation>t = {0} s</translation>
    </message>
</context>
<context>
    <name>PolygonPainter</name>
    <message>
        <source>Velocity polygon</source>
        <translation>速度多边形</translation>
    </message>
    <message>
        <source>Acceleration polygon</source>
        <translation>加速度多边形</translation>
    </message>
    <message>
        <source>Force polygon of the ram group</source>
        <translation>滑枕杆组的力多边形</translation>
    </message>
    <message>
        <source>Force polygon of the lever</source>
        <translation>导杆的力多边形</translation>
    </message>
    <message>
        <source>Every vector is zero at this position.</source>
        <translation>此位置所有矢量均为零。</translation>
    </message>
    <message>
        <source>Limit position: the lever is at rest (ω₄ = 0).</source>
        <translation>极限位置：导杆瞬时静止（ω₄ = 0）。</translation>
    </message>
    <message>
        <source>Limit position: ω₄ = 0, so aᵏ = aⁿ = 0.</source>
        <translation>极限位置：ω₄ = 0，故 aᵏ = aⁿ = 0。</translation>
    </message>
    <message>
        <source>Cannot export to '%1': use .png or .svg</source>
        <translation>无法导出为“%1”：请使用 .png 或 .svg</translation>
    </message>
</context>
<context>
    <name>PolygonView</name>
    <message>
        <source>The scale must be a positive number</source>
        <translation>比例尺必须是正数</translation>
    </message>
    <message>
        <source>Export vector diagram</source>
        <translation>导出矢量多边形</translation>
    </message>
    <message>
        <source>SVG drawing (*.svg);;PNG image (*.png)</source>
        <translation>SVG 矢量图 (*.svg);;PNG 图像 (*.png)</translation>
    </message>
    <message>
        <source>Could not write %1: %2</source>
        <translation>无法写入 %1：%2</translation>
    </message>
    <message>
        <source>Automatic scale</source>
        <translation>自动比例尺</translation>
    </message>
    <message>
        <source>The round scale that fills the view at this position</source>
        <translation>在此位置充满视图的整数比例尺</translation>
    </message>
    <message>
        <source>Export…</source>
        <translation>导出…</translation>
    </message>
    <message>
        <source>Save the diagram at true scale as SVG or PNG</source>
        <translation>按真实比例尺保存为 SVG 或 PNG</translation>
    </message>
    <message>
        <source>Show the diagram in a large window, or dock it again; a typed scale μ is kept</source>
        <translation>在大窗口中显示矢量多边形，或放回停靠位置；输入的比例尺 μ 保持不变</translation>
    </message>
</context>
<context>
    <name>PositionsModel</name>
    <message>
        <source>Position</source>
        <translation>位置</translation>
    </message>
</context>
<context>
    <name>PositionsView</name>
    <message>
        <source>Positions:</source>
        <translation>位置数：</translation>
    </message>
    <message>
        <source>Number of equally spaced crank positions, numbered from the limit position that starts the working stroke</source>
        <translation>等分的曲柄位置数，从工作行程起点的极限位置开始编号</translation>
    </message>
    <message>
        <source>Copy</source>
        <translation>复制</translation>
    </message>
    <message>
        <source>Copy the selected rows (or all) as tab-separated text for Excel or WPS</source>
        <translation>将所选行（或全部）复制为制表符分隔文本，可粘贴到 Excel 或 WPS</translation>
    </message>
</context>
<context>
    <name>Progress</name>
    <message>
        <source>Cancel</source>
        <translation>取消</translation>
    </message>
    <message>
        <source>Cancelling…</source>
        <translation>正在取消…</translation>
    </message>
    <message>
        <source>the export's process stopped unexpectedly (exit status %1)</source>
        <translation>导出进程意外终止（退出状态 %1）</translation>
    </message>
</context>
<context>
    <name>Report</name>
    <message>
        <source>Design report: quick-return mechanism of a shaper</source>
        <translation>牛头刨床导杆机构设计说明书</translation>
    </message>
    <message>
        <source>1 Design inputs</source>
        <translation>1 设计数据</translation>
    </message>
    <message>
        <source>2 Synthesized dimensions and validation margins</source>
        <translation>2 尺寸综合结果与校核裕量</translation>
    </message>
    <message>
        <source>3 The mechanism at its limit positions</source>
        <translation>3 机构的两个极限位置</translation>
    </message>
    <message>
        <source>Scheme to scale at the limit positions that start and end the working stroke</source>
        <translation>工作行程起点和终点两个极限位置的机构运动简图（按比例）</translation>
    </message>
    <message>
        <source>4 Motion of the ram and cycle metrics</source>
        <translation>4 滑枕运动与运动特性</translation>
    </message>
    <message>
        <source>Ram displacement, velocity and acceleration over one crank revolution, one curve per speed</source>
        <translation>曲柄转一周滑枕的位移、速度和加速度线图，每个转速一条曲线</translation>
    </message>
    <message>
        <source>5 Kinematic and force analysis at the crank positions</source>
        <translation>5 各曲柄位置的运动分析与动态静力分析</translation>
    </message>
    <message>
        <source>Positions 1 … N are equally spaced from the limit position that starts the working stroke (φ = 0). The shaded rows are the special positions, solved exactly. Forces are on the named body.</source>
        <translation>位置 1 … N 从工作行程起点的极限位置（φ = 0）起等分曲柄圆。带底色的行为精确求解的特殊位置。力为作用在所注构件上的力。</translation>
    </message>
    <message>
        <source>6 Velocity, acceleration and force polygons</source>
        <translation>6 速度多边形、加速度多边形与力多边形</translation>
    </message>
    <message>
        <source>Drawn to scale from the exact solution at %1 r/min; μ is the scale of each drawing (1 mm on the page).</source>
        <translation>按 %1 r/min 的精确解按比例绘制；μ 为各图的比例尺（图上 1 mm 所代表的量）。</translation>
    </message>
    <message>
        <source>7 Crank torque, energy and flywheel</source>
        <translation>7 曲柄驱动力矩、能量与飞轮</translation>
    </message>
    <message>
        <source>&lt;b&gt;Flywheel.&lt;/b&gt; On the crank shaft, %1; the loads are those of section 1.</source>
        <translation>&lt;b&gt;飞轮。&lt;/b&gt;装在曲柄轴上，%1；载荷见第 1 节。</translation>
    </message>
    <message>
        <source>Crank torque, input power, energy fluctuation ΔE and joint forces over one revolution</source>
        <translation>一个运动循环内的曲柄驱动力矩、输入功率、能量变化 ΔE 与运动副反力</translation>
    </message>
    <message>
        <source>No loads were given, so the force analysis is left out. Give the masses and the cutting force (or a design file with loads) to include it.</source>
        <translation>未给出载荷，因此省略力分析。请给出质量和切削力（或含载荷的设计文件）。</translation>
    </message>
    <message>
        <source>8 Conventions and formulas</source>
        <translation>8 约定与公式</translation>
    </message>
    <message>
        <source>%1 The feed cam</source>
        <translation>%1 进给凸轮</translation>
    </message>
    <message>
        <source>The feed cam cannot be made for this design: %1</source>
        <translation>此设计无法得到进给凸轮：%1</translation>
    </message>
    <message>
        <source>Base radius r0 of the pitch curve</source>
        <translation>理论廓线基圆半径 r0</translation>
    </message>
    <message>
        <source>(allowed %1° / %2°)</source>
        <translation>（许用值 %1° / %2°）</translation>
    </message>
    <message>
        <source>(largest %1 mm)</source>
        <translation>（最大可用 %1 mm）</translation>
    </message>
    <message>
        <source>(cut ends at %1°, the next starts %2° later)</source>
        <translation>（切削终止于 %1°，再转 %2° 开始下一次切削）</translation>
    </message>
    <message>
        <source>exceeded</source>
        <translation>超出</translation>
    </message>
    <message>
        <source>(at least hub + clearance = %1 mm)</source>
        <translation>（不小于轮毂半径 + 间隙 = %1 mm）</translation>
    </message>
    <message>
        <source>(at most a − boss − clearance = %1 mm)</source>
        <translation>（不大于 a − 凸台半径 − 间隙 = %1 mm）</translation>
    </message>
    <message>
        <source>base radius raised from %1 mm to take the roller and clear the hub and the pivot boss</source>
        <translation>基圆半径由 %1 mm 增大，以装下滚子并避开轮毂和摆动中心凸台</translation>
    </message>
    <message>
        <source>Centre distance a</source>
        <translation>中心距 a</translation>
    </message>
    <message>
        <source>Follower arm l</source>
        <translation>从动件摆臂长 l</translation>
    </message>
    <message>
        <source>Initial arm angle ψ0</source>
        <translation>初始摆角 ψ0</translation>
    </message>
    <message>
        <source>Max pressure angle, rise / return</source>
        <translation>推程 / 回程最大压力角</translation>
    </message>
    <message>
        <source>Smallest convex radius ρmin of the pitch curve</source>
        <translation>理论廓线最小外凸曲率半径 ρmin</translation>
    </message>
    <message>
        <source>Roller radius r</source>
        <translation>滚子半径 r</translation>
    </message>
    <message>
        <source>Base radius of the profile r0 − r</source>
        <translation>实际廓线基圆半径 r0 − r</translation>
    </message>
    <message>
        <source>Largest radius of the profile R1 − r</source>
        <translation>实际廓线最大半径 R1 − r</translation>
    </message>
    <message>
        <source>Note</source>
        <translation>说明</translation>
    </message>
    <message>
        <source>Follower's largest ω / α at %1 r/min</source>
        <translation>从动件最大 ω / α（%1 r/min）</translation>
    </message>
    <message>
        <source>Pressure angle allowance</source>
        <translation>压力角许用值</translation>
    </message>
    <message>
        <source>Rise starts at crank angle</source>
        <translation>推程起点曲柄转角</translation>
    </message>
    <message>
        <source>The feed cam at the start of the rise, with its follower and roller (the cam turns clockwise)</source>
        <translation>推程起点处的进给凸轮及其从动件和滚子（凸轮顺时针转动）</translation>
    </message>
    <message>
        <source>The follower's angle ψ, angular velocity ω and acceleration α (one curve per crank speed, in the colours of the ram's curves in section 4) and the pressure angle against the cam angle δ; dashed: the allowed pressure angles</source>
        <translation>从动件摆角 ψ、角速度 ω 和角加速度 α（每个曲柄转速一条曲线，颜色同第 4 节滑枕线图）及压力角随凸轮转角 δ 的变化；虚线：许用压力角</translation>
    </message>
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
        <translation>滑枕行程 H</translation>
    </message>
    <message>
        <source>Frame O2O4 L2</source>
        <translation>机架 O2O4 L2</translation>
    </message>
    <message>
        <source>Lever O4B L3</source>
        <translation>导杆 O4B L3</translation>
    </message>
    <message>
        <source>block on the lever tip in a slot of the ram</source>
        <translation>导杆端部滑块在滑枕滑槽中滑动</translation>
    </message>
    <message>
        <source>connecting rod from the lever tip to the ram</source>
        <translation>连杆连接导杆端部与滑枕</translation>
    </message>
    <message>
        <source>Ram drive</source>
        <translation>滑枕驱动方式</translation>
    </message>
    <message>
        <source>through the lever tip's extreme positions</source>
        <translation>通过导杆端点两极限位置</translation>
    </message>
    <message>
        <source>midway along the tip arc's sagitta</source>
        <translation>位于导杆端点圆弧矢高的中点</translation>
    </message>
    <message>
        <source>Ram guide line</source>
        <translation>滑枕导路</translation>
    </message>
    <message>
        <source>trailing the tip</source>
        <translation>滞后于导杆端点</translation>
    </message>
    <message>
        <source>leading the tip</source>
        <translation>超前于导杆端点</translation>
    </message>
    <message>
        <source>Connecting rod</source>
        <translation>连杆</translation>
    </message>
    <message>
        <source>Crank speeds</source>
        <translation>曲柄转速</translation>
    </message>
    <message>
        <source>Loads</source>
        <translation>载荷</translation>
    </message>
    <message>
        <source>none given</source>
        <translation>未给出</translation>
    </message>
    <message>
        <source>trailing</source>
        <translation>后置</translation>
    </message>
    <message>
        <source>leading</source>
        <translation>前置</translation>
    </message>
    <message>
        <source>Extreme-position angle θ</source>
        <translation>极位夹角 θ</translation>
    </message>
    <message>
        <source>Guide line above the lever pivot O4</source>
        <translation>导路距导杆转轴 O4 的高度</translation>
    </message>
    <message>
        <source>Guide line above the crank centre O2, h</source>
        <translation>导路距曲柄转轴 O2 的高度 h</translation>
    </message>
    <message>
        <source>Connecting rod BC L4</source>
        <translation>连杆 BC L4</translation>
    </message>
    <message>
        <source>Time ratio K of the dimensions</source>
        <translation>按尺寸计算的行程速比系数 K</translation>
    </message>
    <message>
        <source>Stroke H of the dimensions</source>
        <translation>按尺寸计算的行程 H</translation>
    </message>
    <message>
        <source>time ratio K ≤ 5</source>
        <translation>行程速比系数 K ≤ 5</translation>
    </message>
    <message>
        <source>lever L3 ≥ L2 + L1 (crank pin stays on the lever)</source>
        <translation>导杆 L3 ≥ L2 + L1（曲柄销始终在导杆上）</translation>
    </message>
    <message>
        <source>guide above L2 + L1 (ram clears the crank)</source>
        <translation>导路高于 L2 + L1（滑枕不碰曲柄）</translation>
    </message>
    <message>
        <source>guide ≤ L3 (block reaches the guide)</source>
        <translation>导路 ≤ L3（滑块能到达导路）</translation>
    </message>
    <message>
        <source>rod reaches the guide over the whole cycle</source>
        <translation>连杆在整个循环中都能到达导路</translation>
    </message>
    <message>
        <source>rod never in line with the lever (no dead centre)</source>
        <translation>连杆不与导杆共线（无死点）</translation>
    </message>
    <message>
        <source>Rule</source>
        <translation>校核条件</translation>
    </message>
    <message>
        <source>Value</source>
        <translation>数值</translation>
    </message>
    <message>
        <source>Limit</source>
        <translation>限值</translation>
    </message>
    <message>
        <source>Margin</source>
        <translation>裕量</translation>
    </message>
    <message>
        <source>Validation margins</source>
        <translation>校核裕量</translation>
    </message>
    <message>
        <source>Measured time ratio K</source>
        <translation>实测行程速比系数 K</translation>
    </message>
    <message>
        <source>Measured stroke</source>
        <translation>实测行程</translation>
    </message>
    <message>
        <source>Working / return crank angle</source>
        <translation>工作 / 回程曲柄转角</translation>
    </message>
    <message>
        <source>Largest pressure angle</source>
        <translation>最大压力角</translation>
    </message>
    <message>
        <source>Crank speed</source>
        <translation>曲柄转速</translation>
    </message>
    <message>
        <source>Working / return time</source>
        <translation>工作 / 回程时间</translation>
    </message>
    <message>
        <source>Max cutting speed</source>
        <translation>最大切削速度</translation>
    </message>
    <message>
        <source>Mean cutting speed</source>
        <translation>平均切削速度</translation>
    </message>
    <message>
        <source>Max return speed</source>
        <translation>最大回程速度</translation>
    </message>
    <message>
        <source>Max |acceleration|</source>
        <translation>最大 |加速度|</translation>
    </message>
    <message>
        <source>Cycle metrics per crank speed</source>
        <translation>各转速下的运动特性</translation>
    </message>
    <message>
        <source>The whole table is given at the first crank speed, n₁ = %1 r/min; at a speed n the velocities are n/n₁ times and the accelerations (n/n₁)² times those.</source>
        <translation>完整的表只列第一个曲柄转速 n₁ = %1 r/min；转速为 n 时，各速度为其 n/n₁ 倍，各加速度为其 (n/n₁)² 倍。</translation>
    </message>
    <message>
        <source>The ram's velocity and acceleration, the crank torque and the power follow at every speed.</source>
        <translation>随后列出各转速下滑枕的速度和加速度、曲柄驱动力矩和功率。</translation>
    </message>
    <message>
        <source>The ram's velocity and acceleration follow at every speed.</source>
        <translation>随后列出各转速下滑枕的速度和加速度。</translation>
    </message>
    <message>
        <source>Every column at every speed: shaper table.</source>
        <translation>各转速下的全部各列：shaper table。</translation>
    </message>
    <message>
        <source>At every crank speed: %1</source>
        <translation>各曲柄转速下：%1</translation>
    </message>
    <message>
        <source>No.</source>
        <translation>序号</translation>
    </message>
    <message>
        <source>Position</source>
        <translation>位置</translation>
    </message>
    <message>
        <source>Lever weight G_4</source>
        <translation>导杆重量 G_4</translation>
    </message>
    <message>
        <source>Lever centre of mass l_O4S4 (from O4)</source>
        <translation>导杆质心 l_O4S4（自 O4）</translation>
    </message>
    <message>
        <source>Lever inertia J_S4 (about S_4)</source>
        <translation>导杆转动惯量 J_S4（对 S_4）</translation>
    </message>
    <message>
        <source>Ram weight G_6 (with the tool)</source>
        <translation>滑枕重量 G_6（含刀具）</translation>
    </message>
    <message>
        <source>Ram centre of mass x_S6, y_S6 (from C, x along the cut, y up)</source>
        <translation>滑枕质心 x_S6、y_S6（自 C，x 沿切削方向，y 向上）</translation>
    </message>
    <message>
        <source>Rod mass m_5</source>
        <translation>连杆质量 m_5</translation>
    </message>
    <message>
        <source>Block mass, crank mass</source>
        <translation>滑块质量、曲柄质量</translation>
    </message>
    <message>
        <source>Cutting force P, tool below the guide y_P</source>
        <translation>切削力 P，刀尖在导路下 y_P</translation>
    </message>
    <message>
        <source>Idle margin at each end of the stroke</source>
        <translation>行程两端的空刀量</translation>
    </message>
    <message>
        <source>Gravity</source>
        <translation>重力</translation>
    </message>
    <message>
        <source>on</source>
        <translation>计入</translation>
    </message>
    <message>
        <source>off</source>
        <translation>不计</translation>
    </message>
    <message>
        <source>Ram guide length</source>
        <translation>滑枕导路长度</translation>
    </message>
    <message>
        <source> (the stroke H)</source>
        <translation>（行程 H）</translation>
    </message>
    <message>
        <source>Coefficient of speed fluctuation δ</source>
        <translation>速度不均匀系数 δ</translation>
    </message>
    <message>
        <source>Other rotating parts (J, speed)</source>
        <translation>其他转动构件（J，转速）</translation>
    </message>
    <message>
        <source>Contents</source>
        <translation>目录</translation>
    </message>
    <message>
        <source>%1, φ = %2°</source>
        <translation>%1，φ = %2°</translation>
    </message>
    <message>
        <source>Figure %1. </source>
        <translation>图 %1  </translation>
    </message>
    <message>
        <source>J = %1 kg·m² at %2·ω2</source>
        <translation>J = %1 kg·m²，转速 %2·ω2</translation>
    </message>
    <message>
        <source>; </source>
        <translation>；</translation>
    </message>
    <message>
        <source>parabolic</source>
        <translation>等加速等减速</translation>
    </message>
    <message>
        <source>cosine</source>
        <translation>余弦加速度</translation>
    </message>
    <message>
        <source>sine (cycloidal)</source>
        <translation>正弦加速度（摆线）</translation>
    </message>
    <message>
        <source>3-4-5 polynomial</source>
        <translation>3-4-5 多项式</translation>
    </message>
    <message>
        <source>auto</source>
        <translation>自动</translation>
    </message>
    <message>
        <source>Cam: follower arm l, swing ψmax</source>
        <translation>凸轮：从动件摆臂长 l，摆角 ψmax</translation>
    </message>
    <message>
        <source>Cam: rise, outer dwell, return</source>
        <translation>凸轮：推程角、远休止角、回程角</translation>
    </message>
    <message>
        <source>Cam: rise law, return law</source>
        <translation>凸轮：推程运动规律、回程运动规律</translation>
    </message>
    <message>
        <source>Cam: allowed pressure angle, rise / return</source>
        <translation>凸轮：许用压力角，推程 / 回程</translation>
    </message>
    <message>
        <source>Cam: roller, base radius, centre distance</source>
        <translation>凸轮：滚子半径、基圆半径、中心距</translation>
    </message>
    <message>
        <source>Cam: rise at crank angle</source>
        <translation>凸轮：推程起始曲柄转角</translation>
    </message>
    <message>
        <source>Gears: teeth z_1, z_2, module m</source>
        <translation>齿轮：齿数 z_1、z_2，模数 m</translation>
    </message>
    <message>
        <source>Gears: shifts x_1, x_2, centre distance a′</source>
        <translation>齿轮：变位系数 x_1、x_2，中心距 a′</translation>
    </message>
    <message>
        <source>; the flywheel needed is J&lt;sub&gt;F&lt;/sub&gt; − J&lt;sub&gt;c&lt;/sub&gt;, with the other rotating parts reduced to the crank J&lt;sub&gt;c&lt;/sub&gt; = Σ J&lt;sub&gt;i&lt;/sub&gt;·(ω&lt;sub&gt;i&lt;/sub&gt;/ω&lt;sub&gt;2&lt;/sub&gt;)&lt;sup&gt;2&lt;/sup&gt; (none when J&lt;sub&gt;c&lt;/sub&gt; ≥ J&lt;sub&gt;F&lt;/sub&gt;)</source>
        <translation>；所需飞轮为 J&lt;sub&gt;F&lt;/sub&gt; − J&lt;sub&gt;c&lt;/sub&gt;，其中其他转动构件等效到曲柄 J&lt;sub&gt;c&lt;/sub&gt; = Σ J&lt;sub&gt;i&lt;/sub&gt;·(ω&lt;sub&gt;i&lt;/sub&gt;/ω&lt;sub&gt;2&lt;/sub&gt;)&lt;sup&gt;2&lt;/sup&gt;（J&lt;sub&gt;c&lt;/sub&gt; ≥ J&lt;sub&gt;F&lt;/sub&gt; 时无需飞轮）</translation>
    </message>
    <message>
        <source>Mean / max crank torque</source>
        <translation>平均 / 最大曲柄驱动力矩</translation>
    </message>
    <message>
        <source>Mean power (motor, before efficiency)</source>
        <translation>平均功率（电动机，未计效率）</translation>
    </message>
    <message>
        <source>Energy fluctuation ΔW_max</source>
        <translation>最大盈亏功 ΔW_max</translation>
    </message>
    <message>
        <source>Flywheel J_F on the crank shaft</source>
        <translation>曲柄轴上的飞轮转动惯量 J_F</translation>
    </message>
    <message>
        <source>Flywheel J_F − J_e (net)</source>
        <translation>飞轮 J_F − J_e（净值）</translation>
    </message>
    <message>
        <source>Rotating parts at the crank J_c</source>
        <translation>其他转动构件等效到曲柄 J_c</translation>
    </message>
    <message>
        <source>Flywheel needed J_F − J_c</source>
        <translation>所需飞轮 J_F − J_c</translation>
    </message>
    <message>
        <source>Flywheel J_F − J_c − J_e (net)</source>
        <translation>飞轮 J_F − J_c − J_e（净）</translation>
    </message>
    <message>
        <source>Mean reduced inertia J_e</source>
        <translation>平均等效转动惯量 J_e</translation>
    </message>
    <message>
        <source>Torque, power and flywheel per crank speed</source>
        <translation>各转速下的力矩、功率与飞轮</translation>
    </message>
    <message>
        <source>&lt;b&gt;Synthesis.&lt;/b&gt; θ = 180°·(K − 1)/(K + 1); L2 = L1/sin(θ/2); L3 = H/(2·sin(θ/2)); guide midway along the sagitta of the tip's arc, at L3·(1 + cos(θ/2))/2 above O4.</source>
        <translation>&lt;b&gt;尺寸综合。&lt;/b&gt;θ = 180°·(K − 1)/(K + 1)；L2 = L1/sin(θ/2)；L3 = H/(2·sin(θ/2))；导路位于导杆端点圆弧矢高的中点，距 O4 为 L3·(1 + cos(θ/2))/2。</translation>
    </message>
    <message>
        <source>&lt;b&gt;Synthesis.&lt;/b&gt; θ = 180°·(K − 1)/(K + 1); L2 = L1/sin(θ/2); L3 = H/(2·sin(θ/2)); guide at the height given above O4.</source>
        <translation>&lt;b&gt;尺寸综合。&lt;/b&gt;θ = 180°·(K − 1)/(K + 1)；L2 = L1/sin(θ/2)；L3 = H/(2·sin(θ/2))；导路位于给定高度（距 O4）。</translation>
    </message>
    <message>
        <source>&lt;b&gt;Dimensions.&lt;/b&gt; L1, L2 and L3 as given; θ = 2·arcsin(L1/L2), K = (180° + θ)/(180° − θ), H = 2·L3·sin(θ/2); guide through the tip's extreme positions at L3·cos(θ/2) above O4.</source>
        <translation>&lt;b&gt;给定尺寸。&lt;/b&gt;L1、L2、L3 为给定值；θ = 2·arcsin(L1/L2)，K = (180° + θ)/(180° − θ)，H = 2·L3·sin(θ/2)；导路通过导杆端点两极限位置，距 O4 为 L3·cos(θ/2)。</translation>
    </message>
    <message>
        <source>&lt;b&gt;Dimensions.&lt;/b&gt; L1, L2 and L3 as given; θ = 2·arcsin(L1/L2), K = (180° + θ)/(180° − θ), H = 2·L3·sin(θ/2); guide midway along the sagitta of the tip's arc, at L3·(1 + cos(θ/2))/2 above O4.</source>
        <translation>&lt;b&gt;给定尺寸。&lt;/b&gt;L1、L2、L3 为给定值；θ = 2·arcsin(L1/L2)，K = (180° + θ)/(180° − θ)，H = 2·L3·sin(θ/2)；导路位于导杆端点圆弧矢高的中点，距 O4 为 L3·(1 + cos(θ/2))/2。</translation>
    </message>
    <message>
        <source>&lt;b&gt;Dimensions.&lt;/b&gt; L1, L2 and L3 as given; θ = 2·arcsin(L1/L2), K = (180° + θ)/(180° − θ), H = 2·L3·sin(θ/2); guide at the height given above O4.</source>
        <translation>&lt;b&gt;给定尺寸。&lt;/b&gt;L1、L2、L3 为给定值；θ = 2·arcsin(L1/L2)，K = (180° + θ)/(180° − θ)，H = 2·L3·sin(θ/2)；导路位于给定高度（距 O4）。</translation>
    </message>
    <message>
        <source>&lt;b&gt;Frame and signs.&lt;/b&gt; Lever pivot O4 at the origin, crank centre O2 at (0, L2) above it, ram guide the line y = guide height; the ram cuts toward +x and the crank turns clockwise. Crank angle φ = 0 at the limit position that starts the working stroke, increasing with rotation; 0 … 180° + θ is the working stroke. Ram x, v and a are positive in the cutting direction, x measured from the position at φ = 0. The lever angle ψ is measured from O4→O2, positive toward the cut. Links as in the task book: 1 frame, 2 crank O2A, 3 block at A, 4 lever O4B, 5 rod BC (in the block variant the block at B), 6 ram; S4 and S6 are the lever's and the ram's centres of mass. Forces are those on the named body, torque positive in the direction of rotation.</source>
        <translation>&lt;b&gt;坐标与符号。&lt;/b&gt;导杆转轴 O4 为原点，曲柄转轴 O2 位于其正上方 (0, L2)，滑枕导路为直线 y = 导路高度；滑枕向 +x 方向切削，曲柄顺时针转动。曲柄转角 φ 在工作行程起点的极限位置为 0，沿转动方向增大；0 … 180° + θ 为工作行程。滑枕 x、v、a 以切削方向为正，x 从 φ = 0 时的位置量起。导杆角 ψ 从 O4→O2 量起，偏向切削方向为正。构件编号（同任务书）：1 机架，2 曲柄 O2A，3 滑块 A，4 导杆 O4B，5 连杆 BC（滑块方案中为 B 处的滑块），6 滑枕；S4、S6 为导杆和滑枕的质心。力为作用在所注构件上的力，力矩以曲柄转向为正。</translation>
    </message>
    <message>
        <source>&lt;b&gt;Synthesis.&lt;/b&gt; θ = 180°·(K − 1)/(K + 1); L2 = L1/sin(θ/2); L3 = H/(2·sin(θ/2)); guide through the tip's extreme positions at L3·cos(θ/2) above O4 (h = H/(2·tan(θ/2)) − L2 above O2).</source>
        <translation>&lt;b&gt;尺寸综合。&lt;/b&gt;θ = 180°·(K − 1)/(K + 1)；L2 = L1/sin(θ/2)；L3 = H/(2·sin(θ/2))；导路通过导杆端点两极限位置，距 O4 为 L3·cos(θ/2)（距 O2 为 h = H/(2·tan(θ/2)) − L2）。</translation>
    </message>
    <message>
        <source>none needed (J_c ≥ J_F)</source>
        <translation>无需飞轮 (J_c ≥ J_F)</translation>
    </message>
    <message>
        <source>&lt;b&gt;Senses.&lt;/b&gt; The lever's ω4 and α4 are positive clockwise (as ψ and the crank), the rod's ω5 and α5 counter-clockwise. The block's sliding speed is positive away from O4 and its Coriolis acceleration 2·ω4·v_slide is the component along the direction of increasing ψ; the polygons' v_A4A3 and a^k_A4A3 are their negatives. The cutting force acts from the start to the end of the cut, both included: the rows at those angles show it acting.</source>
        <translation>&lt;b&gt;正方向。&lt;/b&gt;导杆的 ω4、α4 以顺时针为正（与 ψ 及曲柄转向相同），连杆的 ω5、α5 以逆时针为正。滑块沿导杆的滑动速度以离开 O4 为正，其科氏加速度 2·ω4·v_slide 取沿 ψ 增大方向的分量；矢量多边形中的 v_A4A3 与 a^k_A4A3 为其相反数。切削力从切削开始到切削结束均作用（两端包括在内）：这两个位置的行计入切削力。</translation>
    </message>
    <message>
        <source>&lt;b&gt;Velocities.&lt;/b&gt; v_A4 = v_A3 + v_A4A3 with v_A3 = v_A2 = ω2·L1 ⟂ O2A, v_A4 = ω4·O4A ⟂ O4A, v_A4A3 ∥ O4A; v_B = ω4·L3; block variant v_C = v_B + v_CB (v_CB vertical), rod variant v_C = v_B + v_CB with v_CB = ω5·L4 ⟂ BC.</source>
        <translation>&lt;b&gt;速度分析。&lt;/b&gt;v_A4 = v_A3 + v_A4A3，其中 v_A3 = v_A2 = ω2·L1 ⟂ O2A，v_A4 = ω4·O4A ⟂ O4A，v_A4A3 ∥ O4A；v_B = ω4·L3；滑块方案 v_C = v_B + v_CB（v_CB 沿铅垂方向），连杆方案 v_C = v_B + v_CB，v_CB = ω5·L4 ⟂ BC。</translation>
    </message>
    <message>
        <source>&lt;b&gt;Accelerations.&lt;/b&gt; a_A4 = a^n_A4 + a^t_A4 = a_A3 + a^k_A4A3 + a^r_A4A3, a^n_A4 = ω4²·O4A toward O4, a^t_A4 = α4·O4A, Coriolis a^k_A4A3 = 2·ω4·v_A4A3 (v_A4A3 turned 90° in the sense of ω4); a_C = a_B + a^n_CB + a^t_CB (rod) with a^n_CB = ω5²·L4, a^t_CB = α5·L4.</source>
        <translation>&lt;b&gt;加速度分析。&lt;/b&gt;a_A4 = a^n_A4 + a^t_A4 = a_A3 + a^k_A4A3 + a^r_A4A3，a^n_A4 = ω4²·O4A 指向 O4，a^t_A4 = α4·O4A，哥氏加速度 a^k_A4A3 = 2·ω4·v_A4A3（将 v_A4A3 沿 ω4 转向转 90°）；连杆方案 a_C = a_B + a^n_CB + a^t_CB，a^n_CB = ω5²·L4，a^t_CB = α5·L4。</translation>
    </message>
    <message>
        <source>&lt;b&gt;Forces.&lt;/b&gt; Kinetostatics at constant crank speed (d'Alembert): inertia forces F_I = −m·a_S and moments −J·α are applied and each link is in equilibrium; joints are frictionless. The cutting force P acts against the cut between idle·H and (1 − idle)·H of the working stroke.</source>
        <translation>&lt;b&gt;力分析。&lt;/b&gt;曲柄匀速转动下的动态静力分析（达朗贝尔原理）：加上惯性力 F_I = −m·a_S 和惯性力矩 −J·α 后各构件处于平衡；运动副无摩擦。切削力 P 与切削方向相反，作用于工作行程的空刀量·H 至 (1 − 空刀量)·H 之间。</translation>
    </message>
    <message>
        <source>&lt;b&gt;Flywheel.&lt;/b&gt; M_m = (1/2π)∮M dφ; P_m = M_m·ω; ΔW_max = max − min of ∫(M − M_m) dφ; J_F = ΔW_max/(ω²·δ) on the crank shaft (on a shaft turning i times faster: J_F/i²).</source>
        <translation>&lt;b&gt;飞轮。&lt;/b&gt;M_m = (1/2π)∮M dφ；P_m = M_m·ω；ΔW_max 为 ∫(M − M_m) dφ 的最大值与最小值之差；曲柄轴上 J_F = ΔW_max/(ω²·δ)（装在转速为其 i 倍的轴上时为 J_F/i²）。</translation>
    </message>
    <message>
        <source>&lt;b&gt;Method.&lt;/b&gt; All values are computed in closed form from the exact position solution and its derivatives (no numerical differentiation); special positions are exact roots. Every number equals the output of the shaper command line for the same inputs.</source>
        <translation>&lt;b&gt;计算方法。&lt;/b&gt;所有数值均由精确位置解及其导数以解析式计算（不用数值微分）；特殊位置为精确求根结果。每个数值都与相同输入下 shaper 命令行的输出一致。</translation>
    </message>
    <message>
        <source>φ = %1° (limit position)</source>
        <translation>φ = %1°（极限位置）</translation>
    </message>
    <message>
        <source>Feed cam</source>
        <translation>进给凸轮</translation>
    </message>
    <message>
        <source>Design comparison</source>
        <translation>设计比较</translation>
    </message>
    <message>
        <source>Design report</source>
        <translation>设计说明书</translation>
    </message>
    <message>
        <source>Page %1 / %2</source>
        <translation>第 %1 / %2 页</translation>
    </message>
    <message>
        <source>Figure</source>
        <translation>指标</translation>
    </message>
    <message>
        <source>Figures at %1 r/min</source>
        <translation>%1 r/min 时的指标</translation>
    </message>
    <message>
        <source>, </source>
        <translation>、</translation>
    </message>
    <message>
        <source>The design of this report, “%1”, beside %2 at %3 r/min, the report's first speed. Each value is followed by its difference from “%1” in brackets ((=): the same); ★ marks the best value of a row: the lowest max |a|, pressure angle, torques and flywheel J_F. Torques and J_F need loads; a design without them has none (—). The numbers are those of shaper library compare.</source>
        <translation>本说明书的设计“%1”与 %2 在 %3 r/min（本说明书的第一个转速）下的比较。每个数值后的括号内为其与“%1”之差（(=)：相同）；★ 标出每行的最优值：最大 |a|、压力角、驱动力矩和飞轮 J_F 均以小为优。驱动力矩和 J_F 需要载荷；未给载荷的设计没有这些值（—）。数值与 shaper library compare 的输出相同。</translation>
    </message>
    <message>
        <source>9 Comparison with other designs</source>
        <translation>9 与其他设计的比较</translation>
    </message>
    <message>
        <source>Ram displacement, velocity, acceleration and crank torque of the compared designs over one crank revolution</source>
        <translation>所比较各设计在曲柄一转中的滑枕位移、速度、加速度和曲柄驱动力矩</translation>
    </message>
    <message>
        <source>Design name</source>
        <translation>设计名称</translation>
    </message>
    <message>
        <source>Date</source>
        <translation>日期</translation>
    </message>
    <message>
        <source>Student</source>
        <translation>学生</translation>
    </message>
    <message>
        <source>%1 (continued)</source>
        <translation>%1（续）</translation>
    </message>
    <message>
        <source>Student number</source>
        <translation>学号</translation>
    </message>
    <message>
        <source>Class</source>
        <translation>班级</translation>
    </message>
    <message>
        <source>School</source>
        <translation>学院</translation>
    </message>
    <message>
        <source>Supervisor</source>
        <translation>指导教师</translation>
    </message>
    <message>
        <source>Meshing without backlash.</source>
        <translation>无侧隙啮合。</translation>
    </message>
    <message>
        <source>Least shift without undercut.</source>
        <translation>不根切的最小变位系数。</translation>
    </message>
    <message>
        <source>Each gear.</source>
        <translation>各齿轮。</translation>
    </message>
    <message>
        <source>Line of action and contact ratio.</source>
        <translation>啮合线与重合度。</translation>
    </message>
    <message>
        <source>%1 The gear pair</source>
        <translation>%1 齿轮机构</translation>
    </message>
    <message>
        <source>The gear pair cannot be made: %1</source>
        <translation>无法设计该齿轮副：%1</translation>
    </message>
    <message>
        <source>The pair in mesh at a′ = %1 mm, to scale %2 (μl = %3 m/mm), the teeth as the rack cuts them; the pinion 1 drives counter-clockwise. N1N2 the line of action, B1B2 the actual one, P the pitch point</source>
        <translation>中心距 a′ = %1 mm 处啮合的齿轮副，比例 %2（μl = %3 m/mm），齿廓为齿条刀具展成所得；小齿轮 1 为主动轮，逆时针转动。N1N2 为理论啮合线，B1B2 为实际啮合线，P 为节点</translation>
    </message>
    <message>
        <source>Teeth z_1 / z_2</source>
        <translation>齿数 z_1 / z_2</translation>
    </message>
    <message>
        <source>Module m</source>
        <translation>模数 m</translation>
    </message>
    <message>
        <source>m = %1 mm is not a module of GB/T 1357's first series</source>
        <translation>m = %1 mm 不是 GB/T 1357 第一系列的模数</translation>
    </message>
    <message>
        <source>Basic rack α, h_a*, c*</source>
        <translation>基本齿条 α、h_a*、c*</translation>
    </message>
    <message>
        <source>neither shifts nor a centre distance (the rule)</source>
        <translation>既未给定变位系数也未给定中心距（按规则确定）</translation>
    </message>
    <message>
        <source>Given</source>
        <translation>给定</translation>
    </message>
    <message>
        <source>Least tip thickness s_a</source>
        <translation>最小齿顶厚 s_a</translation>
    </message>
    <message>
        <source>Least contact ratio ε</source>
        <translation>最小重合度 ε</translation>
    </message>
    <message>
        <source>The pinion, with fewer teeth, is the one that undercuts, so it gets its least shift without undercut (not below 0) and the gear the rest; if that left the gear undercut, the pinion would give up what the gear needs.</source>
        <translation>小齿轮齿数较少，是会发生根切的一方，因此取其不根切的最小变位系数（不小于 0），其余归大齿轮；若大齿轮因此根切，则小齿轮让出大齿轮所需的部分。</translation>
    </message>
    <message>
        <source>The shifts x_1 = %1 and x_2 = %2 are given; α′ and a′ follow from the no-backlash condition. Least shifts without undercut: x_1min = %3, x_2min = %4.</source>
        <translation>给定变位系数 x_1 = %1、x_2 = %2；α′ 与 a′ 由无侧隙啮合条件求得。不根切的最小变位系数：x_1min = %3，x_2min = %4。</translation>
    </message>
    <message>
        <source>The centre distance a′ = %7 mm is given: the no-backlash condition asks x_1 + x_2 = %8, shared out as x_1 = %1, x_2 = %2 (x_1min = %3, x_2min = %4).</source>
        <translation>给定中心距 a′ = %7 mm：由无侧隙啮合条件得 x_1 + x_2 = %8，分配为 x_1 = %1、x_2 = %2（x_1min = %3，x_2min = %4）。</translation>
    </message>
    <message>
        <source>Neither shifts nor a centre distance are given, and z_1 + z_2 = %5 ≥ 2 z_min = %6: the pinion gets its least shift without undercut, x_1 = max(x_1min, 0) = %1, and the gear x_2 = −x_1 = %2, so a′ = a = %7 mm (a height-modified pair).</source>
        <translation>未给定变位系数和中心距，且 z_1 + z_2 = %5 ≥ 2 z_min = %6：小齿轮取不根切的最小变位系数 x_1 = max(x_1min, 0) = %1，大齿轮取 x_2 = −x_1 = %2，故 a′ = a = %7 mm（高度变位齿轮传动）。</translation>
    </message>
    <message>
        <source>Neither shifts nor a centre distance are given, and z_1 + z_2 = %5 &lt; 2 z_min = %6, so x_2 = −x_1 would undercut the gear: the least positive pair (x_1min = %3, x_2min = %4) meshes at %9 mm, rounded up to a multiple of %10 mm (about m/10) a′ = %7 mm, which asks x_1 + x_2 = %8, shared out as x_1 = %1, x_2 = %2.</source>
        <translation>未给定变位系数和中心距，且 z_1 + z_2 = %5 &lt; 2 z_min = %6，取 x_2 = −x_1 时大齿轮将根切：最小的正变位组合（x_1min = %3，x_2min = %4）在中心距 %9 mm 处啮合，按 %10 mm（约 m/10）的倍数向上圆整得 a′ = %7 mm，由此得 x_1 + x_2 = %8，分配为 x_1 = %1、x_2 = %2。</translation>
    </message>
    <message>
        <source>Centre distance a′ (a)</source>
        <translation>中心距 a′ (a)</translation>
    </message>
    <message>
        <source>Working pressure angle α′</source>
        <translation>啮合角 α′</translation>
    </message>
    <message>
        <source>Centre distance shift factor y / addendum reduction factor Δy</source>
        <translation>中心距变动系数 y / 齿顶高降低系数 Δy</translation>
    </message>
    <message>
        <source>Line of action N1N2 / actual line of action B1B2</source>
        <translation>理论啮合线 N1N2 / 实际啮合线 B1B2</translation>
    </message>
    <message>
        <source>Base pitch pb</source>
        <translation>基圆齿距 pb</translation>
    </message>
    <message>
        <source>Contact ratio ε</source>
        <translation>重合度 ε</translation>
    </message>
    <message>
        <source>Teeth z</source>
        <translation>齿数 z</translation>
    </message>
    <message>
        <source>Shift factor x</source>
        <translation>变位系数 x</translation>
    </message>
    <message>
        <source>Least shift x_min</source>
        <translation>最小变位系数 x_min</translation>
    </message>
    <message>
        <source>Reference radius r (mm)</source>
        <translation>分度圆半径 r (mm)</translation>
    </message>
    <message>
        <source>Base radius r_b (mm)</source>
        <translation>基圆半径 r_b (mm)</translation>
    </message>
    <message>
        <source>Tip radius r_a (mm)</source>
        <translation>齿顶圆半径 r_a (mm)</translation>
    </message>
    <message>
        <source>Root radius r_f (mm)</source>
        <translation>齿根圆半径 r_f (mm)</translation>
    </message>
    <message>
        <source>Working pitch radius r′ (mm)</source>
        <translation>节圆半径 r′ (mm)</translation>
    </message>
    <message>
        <source>Tooth thickness s on the reference circle (mm)</source>
        <translation>分度圆齿厚 s (mm)</translation>
    </message>
    <message>
        <source>Space e on the reference circle (mm)</source>
        <translation>分度圆齿槽宽 e (mm)</translation>
    </message>
    <message>
        <source>Tip thickness s_a (mm)</source>
        <translation>齿顶厚 s_a (mm)</translation>
    </message>
    <message>
        <source>Profile angle at the tip α_a (°)</source>
        <translation>齿顶圆压力角 α_a (°)</translation>
    </message>
    <message>
        <source>Quantity</source>
        <translation>名称</translation>
    </message>
    <message>
        <source>Pinion 1</source>
        <translation>小齿轮 1</translation>
    </message>
    <message>
        <source>Gear 2</source>
        <translation>大齿轮 2</translation>
    </message>
    <message>
        <source>The two gears</source>
        <translation>两齿轮的参数</translation>
    </message>
    <message>
        <source>No undercut of gear %1: x_%1 ≥ x_%1min</source>
        <translation>齿轮 %1 不根切：x_%1 ≥ x_%1min</translation>
    </message>
    <message>
        <source>Tip thickness of gear %1: s_a%1 ≥ %3</source>
        <translation>齿轮 %1 的齿顶厚：s_a%1 ≥ %3</translation>
    </message>
    <message>
        <source>Contact ratio ε ≥ %1</source>
        <translation>重合度 ε ≥ %1</translation>
    </message>
    <message>
        <source>No interference at the root of gear %1 (N_%1 to the tip of gear %2)</source>
        <translation>齿轮 %1 齿根无干涉（N_%1 至齿轮 %2 齿顶）</translation>
    </message>
    <message>
        <source>ok</source>
        <translation>合格</translation>
    </message>
    <message>
        <source>fails</source>
        <translation>不合格</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
    <message>
        <source>Check</source>
        <translation>校验项目</translation>
    </message>
    <message>
        <source>Result</source>
        <translation>结果</translation>
    </message>
    <message>
        <source>The checks</source>
        <translation>校验</translation>
    </message>
    <message>
        <source>Every check passes.</source>
        <translation>各项校验均合格。</translation>
    </message>
    <message>
        <source>What to change:</source>
        <translation>应作的修改：</translation>
    </message>
</context>
<context>
    <name>ReportOptionsDialog</name>
    <message>
        <source>Export design report</source>
        <translation>导出设计说明书</translation>
    </message>
    <message>
        <source>Design name:</source>
        <translation>设计名称：</translation>
    </message>
    <message>
        <source>Student:</source>
        <translation>学生：</translation>
    </message>
    <message>
        <source>Student number:</source>
        <translation>学号：</translation>
    </message>
    <message>
        <source>Class:</source>
        <translation>班级：</translation>
    </message>
    <message>
        <source>School:</source>
        <translation>学院：</translation>
    </message>
    <message>
        <source>Supervisor:</source>
        <translation>指导教师：</translation>
    </message>
    <message>
        <source>Date:</source>
        <translation>日期：</translation>
    </message>
    <message>
        <source>Positions in the table:</source>
        <translation>位置表中的位置数：</translation>
    </message>
    <message>
        <source>Vector diagrams at φ (working stroke):</source>
        <translation>矢量多边形位置 φ（工作行程）：</translation>
    </message>
    <message>
        <source>Vector diagrams at φ (return stroke):</source>
        <translation>矢量多边形位置 φ（回程）：</translation>
    </message>
    <message>
        <source>Include the comparison</source>
        <translation>包含设计比较</translation>
    </message>
    <message>
        <source>Add designs on the Compare tab to compare this design with them.</source>
        <translation>在“比较”选项卡中加入设计，即可与本设计比较。</translation>
    </message>
    <message>
        <source>The Compare tab has %1 designs besides this one; a report compares at most %2.</source>
        <translation>“比较”选项卡中除本设计外有 %1 个设计；说明书最多比较 %2 个。</translation>
    </message>
    <message>
        <source>This design beside the Compare tab's designs (%1) at %2 r/min.</source>
        <translation>本设计与“比较”选项卡中的设计（%1）在 %2 r/min 下比较。</translation>
    </message>
    <message>
        <source>PDF document (*.pdf)</source>
        <translation>PDF 文档 (*.pdf)</translation>
    </message>
    <message>
        <source>HTML page (*.html)</source>
        <translation>HTML 网页 (*.html)</translation>
    </message>
    <message>
        <source>A report is written as PDF (.pdf) or HTML (.html, .htm); %1 is neither. Nothing was written.</source>
        <translation>设计说明书只能保存为 PDF（.pdf）或 HTML（.html、.htm）；%1 两者都不是。未写入任何文件。</translation>
    </message>
    <message>
        <source>Writing the report…</source>
        <translation>正在写入说明书…</translation>
    </message>
    <message>
        <source>No font with Chinese characters is installed. Install one (on Debian/Ubuntu: fonts-noto-cjk) or switch the language to English.</source>
        <translation>未安装中文字体。请安装一种（Debian/Ubuntu：fonts-noto-cjk），或将语言切换为英文。</translation>
    </message>
    <message>
        <source>Could not write %1: %2</source>
        <translation>无法写入 %1：%2</translation>
    </message>
    <message>
        <source>The report cannot be made: %1. Nothing was written.</source>
        <translation>无法生成设计说明书：%1。未写入任何文件。</translation>
    </message>
</context>
<context>
    <name>ResultTable</name>
    <message>
        <source>Copy</source>
        <translation>复制</translation>
    </message>
    <message>
        <source>Copy the selected cells (or the whole table) with their titles as tab-separated text</source>
        <translation>将所选单元格（或整张表）连同标题复制为制表符分隔的文本</translation>
    </message>
</context>
<context>
    <name>SaveDialog</name>
    <message>
        <source>Save design to library</source>
        <translation>保存设计到设计库</translation>
    </message>
    <message>
        <source>comma-separated, e.g. final, rod</source>
        <translation>用逗号分隔，例如 final, rod</translation>
    </message>
    <message>
        <source>Name:</source>
        <translation>名称：</translation>
    </message>
    <message>
        <source>Notes:</source>
        <translation>备注：</translation>
    </message>
    <message>
        <source>Tags:</source>
        <translation>标签：</translation>
    </message>
</context>
<context>
    <name>SchemeWidget</name>
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
        <source>Show the joint forces at the chosen crank speed as arrows, to one scale</source>
        <translation>以箭头按同一比例显示所选曲柄转速下的运动副反力</translation>
    </message>
    <message>
        <source>Crank speed of the force arrows</source>
        <translation>受力箭头对应的曲柄转速</translation>
    </message>
    <message>
        <source>Wheel: zoom, drag: pan, double-click: fit, right click: menu</source>
        <translation>滚轮：缩放，拖动：平移，双击：全部显示，右键：菜单</translation>
    </message>
</context>
<context>
    <name>SpeedCombo</name>
    <message>
        <source>%1 r/min</source>
        <translation>%1 r/min</translation>
    </message>
</context>
<context>
    <name>StackView</name>
    <message>
        <source>{0} r/min</source>
        <translation>{0} r/min</translation>
    </message>
</context>
<context>
    <name>StaleFiguresBar</name>
    <message>
        <source>Recomputing the figures…</source>
        <translation>正在重新计算指标…</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>取消</translation>
    </message>
    <message>
        <source>Design library</source>
        <translation>设计库</translation>
    </message>
    <message>
        <source>Could not recompute the figures: %1</source>
        <translation>无法重新计算指标：%1</translation>
    </message>
    <message>
        <source>These designs can no longer be computed; their figures were left as they were:</source>
        <translation>以下设计已无法计算，其指标保持不变：</translation>
    </message>
    <message>
        <source>The figures of %1 design(s) in this library were computed by an older version of Shaper Designer.</source>
        <translation>本设计库中有 %1 个设计的指标由旧版本的牛头刨床机构设计计算。</translation>
    </message>
    <message>
        <source>Recompute</source>
        <translation>重新计算</translation>
    </message>
    <message>
        <source>Recompute their figures from the stored designs</source>
        <translation>按保存的设计重新计算其指标</translation>
    </message>
</context>
<context>
    <name>app</name>
    <message>
        <source>An internal error occurred; the design on screen is unchanged. Details were written to %1.</source>
        <translation>发生内部错误；屏幕上的设计未改变。详细信息已写入 %1。</translation>
    </message>
    <message>
        <source>Shaper Designer</source>
        <translation>牛头刨床机构设计</translation>
    </message>
</context>
<context>
    <name>figures</name>
    <message>
        <source>Name</source>
        <translation>名称</translation>
    </message>
    <message>
        <source>Notes</source>
        <translation>备注</translation>
    </message>
    <message>
        <source>Tags</source>
        <translation>标签</translation>
    </message>
    <message>
        <source>Created (UTC)</source>
        <translation>创建时间 (UTC)</translation>
    </message>
    <message>
        <source>Modified (UTC)</source>
        <translation>修改时间 (UTC)</translation>
    </message>
    <message>
        <source>Variant</source>
        <translation>方案</translation>
    </message>
    <message>
        <source>Rod side</source>
        <translation>连杆位置</translation>
    </message>
    <message>
        <source>K</source>
        <translation>K</translation>
    </message>
    <message>
        <source>H (mm)</source>
        <translation>H (mm)</translation>
    </message>
    <message>
        <source>θ (°)</source>
        <translation>θ (°)</translation>
    </message>
    <message>
        <source>L1 (mm)</source>
        <translation>L1 (mm)</translation>
    </message>
    <message>
        <source>L2 (mm)</source>
        <translation>L2 (mm)</translation>
    </message>
    <message>
        <source>L3 (mm)</source>
        <translation>L3 (mm)</translation>
    </message>
    <message>
        <source>L4 (mm)</source>
        <translation>L4 (mm)</translation>
    </message>
    <message>
        <source>Guide (mm)</source>
        <translation>导路 (mm)</translation>
    </message>
    <message>
        <source>Max pressure angle (°)</source>
        <translation>最大压力角 (°)</translation>
    </message>
    <message>
        <source>Speed (r/min)</source>
        <translation>转速 (r/min)</translation>
    </message>
    <message>
        <source>Max cutting speed (m/s)</source>
        <translation>最大切削速度 (m/s)</translation>
    </message>
    <message>
        <source>Mean cutting speed (m/s)</source>
        <translation>平均切削速度 (m/s)</translation>
    </message>
    <message>
        <source>Max return speed (m/s)</source>
        <translation>最大回程速度 (m/s)</translation>
    </message>
    <message>
        <source>Max |a| (m/s²)</source>
        <translation>最大 |a| (m/s²)</translation>
    </message>
    <message>
        <source>Mean torque (N·m)</source>
        <translation>平均驱动力矩 (N·m)</translation>
    </message>
    <message>
        <source>Peak torque (N·m)</source>
        <translation>最大驱动力矩 (N·m)</translation>
    </message>
    <message>
        <source>Flywheel J_F (kg·m²)</source>
        <translation>飞轮 J_F (kg·m²)</translation>
    </message>
    <message>
        <source>Time ratio K, measured from the motion</source>
        <translation>行程速比系数 K，由运动实测</translation>
    </message>
    <message>
        <source>Ram stroke H, measured from the motion</source>
        <translation>滑枕行程 H，由运动实测</translation>
    </message>
    <message>
        <source>Extreme-position angle θ</source>
        <translation>极位夹角 θ</translation>
    </message>
    <message>
        <source>Crank O2A</source>
        <translation>曲柄 O2A</translation>
    </message>
    <message>
        <source>Frame O2O4</source>
        <translation>机架 O2O4</translation>
    </message>
    <message>
        <source>Lever O4B</source>
        <translation>导杆 O4B</translation>
    </message>
    <message>
        <source>Connecting rod BC (rod variant)</source>
        <translation>连杆 BC（连杆方案）</translation>
    </message>
    <message>
        <source>Ram guide line above the lever pivot O4</source>
        <translation>滑枕导路距导杆支点 O4 的高度</translation>
    </message>
    <message>
        <source>Largest pressure angle at the ram (rod variant); lower is better</source>
        <translation>滑枕处最大压力角（连杆方案）；越小越好</translation>
    </message>
    <message>
        <source>Largest |ram acceleration| over the cycle; lower is better</source>
        <translation>一个周期内滑枕加速度绝对值的最大值；越小越好</translation>
    </message>
    <message>
        <source>Mean crank torque (needs loads); lower is better</source>
        <translation>平均驱动力矩（需载荷）；越小越好</translation>
    </message>
    <message>
        <source>Peak crank torque (needs loads); lower is better</source>
        <translation>最大驱动力矩（需载荷）；越小越好</translation>
    </message>
    <message>
        <source>Flywheel inertia on the crank shaft (needs loads); lower is better</source>
        <translation>曲柄轴上的飞轮转动惯量（需载荷）；越小越好</translation>
    </message>
    <message>
        <source>block</source>
        <translation>滑块</translation>
    </message>
    <message>
        <source>rod</source>
        <translation>连杆</translation>
    </message>
    <message>
        <source>trailing</source>
        <translation>后置</translation>
    </message>
    <message>
        <source>leading</source>
        <translation>前置</translation>
    </message>
</context>
<context>
    <name>help</name>
    <message>
        <source>Shaper Designer %1</source>
        <translation>牛头刨床机构设计 %1</translation>
    </message>
    <message>
        <source>Synthesis, kinematics and kinetostatics of the quick-return mechanism of a shaper (crank, slotted lever, ram).</source>
        <translation>牛头刨床急回机构（曲柄、导杆、滑枕）的尺寸综合、运动分析和动态静力分析。</translation>
    </message>
    <message>
        <source>Lengths in mm, speeds in r/min, ram velocity in m/s, acceleration in m/s², angles in degrees. The crank angle starts at the limit position that begins the working stroke; ram motion is positive in the cutting direction.</source>
        <translation>长度单位 mm，转速 r/min，滑枕速度 m/s，加速度 m/s²，角度单位为度。曲柄转角自开始工作行程的极限位置量起；滑枕运动以切削方向为正。</translation>
    </message>
    <message>
        <source>Help › User guide (F1) explains the conventions, the method and the command line.</source>
        <translation>“帮助 › 使用指南”（F1）介绍约定、计算方法和命令行。</translation>
    </message>
    <message>
        <source>User guide</source>
        <translation>使用指南</translation>
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
        <translation>切削力 P</translation>
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
        <source>Lever weight G4</source>
        <translation>导杆重量 G4</translation>
    </message>
    <message>
        <source>Ram weight G6</source>
        <translation>滑枕重量 G6</translation>
    </message>
    <message>
        <source>Ram guide length</source>
        <translation>滑枕导路长度</translation>
    </message>
    <message>
        <source>Rotating parts</source>
        <translation>其他转动构件</translation>
    </message>
    <message>
        <source>Rotating part J</source>
        <translation>转动构件 J</translation>
    </message>
    <message>
        <source>Rotating part speed ratio</source>
        <translation>转动构件传动比</translation>
    </message>
    <message>
        <source>Design</source>
        <translation>设计</translation>
    </message>
    <message>
        <source>Follower arm l</source>
        <translation>从动件摆臂长 l</translation>
    </message>
    <message>
        <source>Follower swing ψmax</source>
        <translation>从动件最大摆角 ψmax</translation>
    </message>
    <message>
        <source>Allowed pressure angle, rise</source>
        <translation>推程许用压力角</translation>
    </message>
    <message>
        <source>Allowed pressure angle, return</source>
        <translation>回程许用压力角</translation>
    </message>
    <message>
        <source>Rise angle</source>
        <translation>推程运动角</translation>
    </message>
    <message>
        <source>Outer dwell angle</source>
        <translation>远休止角</translation>
    </message>
    <message>
        <source>Return angle</source>
        <translation>回程运动角</translation>
    </message>
    <message>
        <source>Rise law</source>
        <translation>推程运动规律</translation>
    </message>
    <message>
        <source>Return law</source>
        <translation>回程运动规律</translation>
    </message>
    <message>
        <source>Roller radius</source>
        <translation>滚子半径</translation>
    </message>
    <message>
        <source>Base radius r0</source>
        <translation>基圆半径 r0</translation>
    </message>
    <message>
        <source>Centre distance a</source>
        <translation>中心距 a</translation>
    </message>
    <message>
        <source>Phase of the rise</source>
        <translation>推程起点曲柄转角</translation>
    </message>
    <message>
        <source>Hub radius</source>
        <translation>轮毂半径</translation>
    </message>
    <message>
        <source>Pivot boss radius</source>
        <translation>摆动中心凸台半径</translation>
    </message>
    <message>
        <source>Least clearance</source>
        <translation>最小间隙</translation>
    </message>
    <message>
        <source>Input</source>
        <translation>输入方式</translation>
    </message>
    <message>
        <source>Ram drive</source>
        <translation>滑枕驱动方式</translation>
    </message>
    <message>
        <source>Guide height</source>
        <translation>导路高度</translation>
    </message>
    <message>
        <source>Rod given as</source>
        <translation>连杆给定方式</translation>
    </message>
    <message>
        <source>Loads</source>
        <translation>载荷</translation>
    </message>
    <message>
        <source>Feed cam</source>
        <translation>进给凸轮</translation>
    </message>
    <message>
        <source>%1; %2</source>
        <translation>%1；%2</translation>
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
        <source>must be more than %1 to reach the guide line over the whole cycle</source>
        <translation>必须大于 %1，才能在整个周期内够到导路线</translation>
    </message>
    <message>
        <source>cannot be computed for these inputs; try other values</source>
        <translation>无法按这些输入计算，请换用其他数值</translation>
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
        <source>must be more than %1 mm for this crank and K, so that the ram guide its rule places clears the crank</source>
        <translation>对此曲柄长和 K 须大于 %1 mm，按规则确定的滑枕导路才高过曲柄</translation>
    </message>
    <message>
        <source>must be more than %1 mm, so that the ram guide its rule places clears the crank (L2 + L1 = %2 mm above the lever pivot)</source>
        <translation>须大于 %1 mm，按规则确定的滑枕导路才高过曲柄（导杆摆动中心以上 L2 + L1 = %2 mm）</translation>
    </message>
    <message>
        <source>must be at least %1 mm for this crank and K, so that the block on the lever tip reaches the guide height %2 mm</source>
        <translation>对此曲柄长和 K 须不小于 %1 mm，导杆端部的滑块才能到达 %2 mm 高的导路</translation>
    </message>
    <message>
        <source>must be at least the guide height %1 mm, so that the block on the lever tip reaches the guide (and the crank pin stays on the lever: L2 + L1 = %2 mm)</source>
        <translation>须不小于导路高度 %1 mm，导杆端部的滑块才能到达导路（曲柄销也才留在导杆上：L2 + L1 = %2 mm）</translation>
    </message>
    <message>
        <source>must be more than L2 + L1 = %1 mm, so that the crank pin stays on the lever and a ram guide fits between L2 + L1 and the lever tip</source>
        <translation>须大于 L2 + L1 = %1 mm，以使曲柄销始终在导杆上，并在 L2 + L1 与导杆端部之间留出滑枕导路的高度</translation>
    </message>
    <message>
        <source>must be more than %1 mm for this crank and K, so that the crank pin stays on the lever and a ram guide fits between L2 + L1 and the lever tip</source>
        <translation>对此曲柄和 K 须大于 %1 mm，以使曲柄销始终在导杆上，并在 L2 + L1 与导杆端部之间留出滑枕导路的高度</translation>
    </message>
    <message>
        <source>must be more than L2 + L1 = %1 mm and at most the lever length %2 mm, so that the ram clears the crank and the block on the lever tip reaches the guide</source>
        <translation>须高于 L2 + L1 = %1 mm 且不高于导杆长度 %2 mm，使滑枕不与曲柄干涉、导杆端部的滑块能到达导路</translation>
    </message>
    <message>
        <source>the rod passes a dead-centre position against the lever; lengthen it to at least %1 mm or move the guide line</source>
        <translation>连杆与导杆会经过死点位置；请将连杆加长到不小于 %1 mm，或移动导路线</translation>
    </message>
    <message>
        <source>the rod passes a dead-centre position against the lever; raise L4/L3 to at least %1 or move the guide line</source>
        <translation>连杆与导杆会经过死点位置；请将 L4/L3 增大到不小于 %1，或移动导路线</translation>
    </message>
    <message>
        <source>the rod passes a dead-centre position against the lever at every length up to %1 mm; move the guide line</source>
        <translation>连杆长度在 %1 mm 以内时，连杆与导杆总会经过死点位置；请移动导路线</translation>
    </message>
    <message>
        <source>gives %1 samples (angles × speeds) with %2 speeds, more than a design file holds (%3); use a step of at least %4°</source>
        <translation>%2 个转速时产生 %1 个采样点（角度数 × 转速数），超过设计文件的上限 %3；角度步长至少取 %4°</translation>
    </message>
    <message>
        <source>must be more than %1 mm to reach the guide line over the whole cycle</source>
        <translation>须大于 %1 mm，才能在整个循环中到达导路线</translation>
    </message>
    <message>
        <source>must be at least %1 for this crank and stroke, so that the frame and the lever stay at most %2 mm</source>
        <translation>对此曲柄和行程须不小于 %1，以使机架和导杆长度不超过 %2 mm</translation>
    </message>
    <message>
        <source>no K up to %1 keeps the frame and the lever at most %2 mm for this crank and stroke: shorten them</source>
        <translation>K 取不超过 %1 的任何值，机架和导杆都会超过 %2 mm：请缩短曲柄或行程</translation>
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
        <source>gives %1 samples (angles × speeds), more than %2; use a larger step or fewer speeds</source>
        <translation>产生 %1 个采样点（角度数 × 转速数），超过上限 %2；请增大角度步长或减少转速个数</translation>
    </message>
    <message>
        <source>must be given either as a length or as a ratio L4/L3, not both</source>
        <translation>只能以长度或比值 L4/L3 之一给出，不能同时给出</translation>
    </message>
    <message>
        <source>rise + outer dwell + return must fit in 360° (they add up to %1°)</source>
        <translation>推程、远休止与回程运动角之和不得超过 360°（现为 %1°）</translation>
    </message>
    <message>
        <source>rise + outer dwell + return (%1°) must fit in the %2° the crank turns outside the cut</source>
        <translation>推程、远休止与回程运动角之和（%1°）须在切削以外的 %2° 曲柄转角内完成</translation>
    </message>
    <message>
        <source>feeds during the cut: the rise must start between %1° and %2° of crank angle</source>
        <translation>会在切削时进给：推程须在曲柄转角 %1° 至 %2° 之间开始</translation>
    </message>
    <message>
        <source>too large: must be at most %1 mm, or it undercuts the profile (smallest convex radius of the pitch curve %2 mm)</source>
        <translation>过大：不得超过 %1 mm，否则实际廓线失真（理论廓线最小外凸曲率半径 %2 mm）</translation>
    </message>
    <message>
        <source>is too small: no cam within %1 arm lengths keeps the pressure angle within the allowances</source>
        <translation>过小：在 %1 倍摆臂长以内没有能使压力角不超过许用值的凸轮</translation>
    </message>
    <message>
        <source>gives an arm that crosses the line of centres at the end of its swing; give a base radius below %1 mm</source>
        <translation>使摆臂在摆程终点越过中心连线；请取小于 %1 mm 的基圆半径</translation>
    </message>
    <message>
        <source>gives an arm that crosses the line of centres; choose another base radius</source>
        <translation>使摆臂越过中心连线；请另选基圆半径</translation>
    </message>
    <message>
        <source>too large for the hub: must be at most %1 mm, so that the profile's smallest radius r0 − r stays at least hub + clearance = %2 mm</source>
        <translation>对轮毂过大：不得超过 %1 mm，以使实际廓线最小半径 r0 − r 不小于轮毂半径 + 间隙 = %2 mm</translation>
    </message>
    <message>
        <source>must be between %1 and %2 mm on this cam: at least %3 mm for the profile's largest radius R1 − r to stay within a − boss − clearance = %4 mm, at most %5 mm for it to clear the hub and stay round (ρmin = %6 mm)</source>
        <translation>此凸轮的滚子须在 %1 与 %2 mm 之间：不小于 %3 mm，实际廓线最大半径 R1 − r 才不超出 a − 凸台半径 − 间隙 = %4 mm；不大于 %5 mm，廓线才避开轮毂且不失真（ρmin = %6 mm）</translation>
    </message>
    <message>
        <source>no cam within the allowances takes a roller of %1 mm and clears the hub and the pivot boss; an arm of %2 mm gives one</source>
        <translation>许用压力角内没有能装下 %1 mm 滚子并避开轮毂和摆动中心凸台的凸轮；摆臂长 %2 mm 时可以</translation>
    </message>
    <message>
        <source>no cam within the allowances takes a roller of %1 mm and clears the hub and the pivot boss, with any arm up to %2 mm</source>
        <translation>摆臂长不超过 %2 mm 时，许用压力角内没有能装下 %1 mm 滚子并避开轮毂和摆动中心凸台的凸轮</translation>
    </message>
    <message>
        <source>the pitch curve's smallest convex radius ρmin = %1 mm takes no roller of %2 mm or more (that needs ρmin ≥ %3 mm)</source>
        <translation>理论廓线最小外凸曲率半径 ρmin = %1 mm，装不下 %2 mm 及以上的滚子（需 ρmin ≥ %3 mm）</translation>
    </message>
    <message>
        <source>this cam takes no roller: its pitch curve's smallest convex radius ρmin = %1 mm and r0 − hub − clearance = %2 mm leave no room for one</source>
        <translation>此凸轮装不下任何滚子：理论廓线最小外凸曲率半径 ρmin = %1 mm，r0 − 轮毂半径 − 间隙 = %2 mm，没有滚子的余地</translation>
    </message>
    <message>
        <source>this cam takes no roller: the hub and ρmin = %1 mm allow one of at most %2 mm, the pivot boss needs one of at least %3 mm</source>
        <translation>此凸轮装不下任何滚子：轮毂和 ρmin = %1 mm 只容许不大于 %2 mm 的滚子，摆动中心凸台却需要不小于 %3 mm 的滚子</translation>
    </message>
    <message>
        <source>the smallest cam for the allowances takes no roller of %1 mm or more (ρmin = %2 mm)</source>
        <translation>许用压力角下最小的凸轮装不下 %1 mm 及以上的滚子（ρmin = %2 mm）</translation>
    </message>
    <message>
        <source>no roller up to the smallest cam's largest gives a cam within the allowances that clears the hub and the pivot boss</source>
        <translation>不超过最小凸轮最大滚子的任何滚子，都得不到许用压力角内避开轮毂和摆动中心凸台的凸轮</translation>
    </message>
    <message>
        <source>leave the base radius and the centre distance blank, and the synthesis gives r0 = %1 mm for this roller</source>
        <translation>将校核基圆半径和中心距留空，综合对此滚子给出 r0 = %1 mm</translation>
    </message>
    <message>
        <source>leave the base radius and the centre distance blank, and the synthesis gives r0 = %1 mm with a roller of %2 mm</source>
        <translation>将校核基圆半径和中心距留空，综合给出 r0 = %1 mm、滚子 %2 mm</translation>
    </message>
    <message>
        <source>leave the base radius, the centre distance and the roller blank, and the synthesis gives r0 = %1 mm with a roller of %2 mm</source>
        <translation>将校核基圆半径、中心距和滚子留空，综合给出 r0 = %1 mm、滚子 %2 mm</translation>
    </message>
    <message>
        <source>leave the base radius and the centre distance blank, and an arm of %1 mm gives one</source>
        <translation>将校核基圆半径和中心距留空，摆臂长 %1 mm 时可以</translation>
    </message>
    <message>
        <source>leave the base radius, the centre distance and the roller blank, and an arm of %1 mm gives one</source>
        <translation>将校核基圆半径、中心距和滚子留空，摆臂长 %1 mm 时可以</translation>
    </message>
    <message>
        <source>no synthesized cam takes one either, with any arm up to %1 mm</source>
        <translation>摆臂长不超过 %1 mm 时，综合的凸轮也都装不下</translation>
    </message>
    <message>
        <source>left blank, the roller is %1 mm on a base radius raised to %2 mm</source>
        <translation>滚子留空时为 %1 mm，基圆半径增大到 %2 mm</translation>
    </message>
    <message>
        <source>an allowance of %1° gives one</source>
        <translation>许用压力角为 %1° 时可以</translation>
    </message>
    <message>
        <source>a base radius of %1 mm gives one</source>
        <translation>基圆半径取 %1 mm 时可以</translation>
    </message>
    <message>
        <source>a centre distance of %1 mm gives one</source>
        <translation>中心距取 %1 mm 时可以</translation>
    </message>
    <message>
        <source>a return allowance of %1° gives one</source>
        <translation>回程许用压力角为 %1° 时可以</translation>
    </message>
    <message>
        <source>%1° on the rise and the return give one</source>
        <translation>推程和回程许用压力角都为 %1° 时可以</translation>
    </message>
    <message>
        <source>a swing of %1° gives one</source>
        <translation>最大摆角取 %1° 时可以</translation>
    </message>
    <message>
        <source>an arm of %1 mm gives one (no swing down to %2° does)</source>
        <translation>摆臂长 %1 mm 时可以（最大摆角减到 %2° 也不行）</translation>
    </message>
    <message>
        <source>no whole cam takes a roller of %1 mm with these inputs</source>
        <translation>按现有输入，没有能装下 %1 mm 滚子的完整凸轮</translation>
    </message>
    <message>
        <source>no cam within the allowances takes a roller of %1 mm or more and clears the hub and the pivot boss</source>
        <translation>许用压力角内没有能装下 %1 mm 及以上滚子并避开轮毂和摆动中心凸台的凸轮</translation>
    </message>
    <message>
        <source>a swing of %1° gives one (no allowance up to %2° does)</source>
        <translation>最大摆角取 %1° 时可以（许用压力角加到 %2° 也不行）</translation>
    </message>
    <message>
        <source>no allowance up to %1° gives one, nor a smaller swing: change the arm, the program, the hub, the pivot boss or the clearance</source>
        <translation>许用压力角加到 %1° 也不行，减小最大摆角也不行：请修改摆臂长、运动规律与各段转角、轮毂半径、摆动中心凸台半径或最小间隙</translation>
    </message>
    <message>
        <source>leave the roller blank, and a swing of %1° gives one</source>
        <translation>将滚子留空，最大摆角取 %1° 时可以</translation>
    </message>
    <message>
        <source>leave the roller blank, and an arm of %1 mm gives one</source>
        <translation>将滚子留空，摆臂长 %1 mm 时可以</translation>
    </message>
    <message>
        <source>no smaller swing gives one either, nor, with the roller left blank, a swing or an arm: change the hub, the pivot boss, the clearance, the allowances or the program</source>
        <translation>减小最大摆角也不行，将滚子留空后改最大摆角或摆臂长也不行：请修改轮毂半径、摆动中心凸台半径、最小间隙、许用压力角或运动规律与各段转角</translation>
    </message>
    <message>
        <source>looking for a swing, else an arm, that gives one…</source>
        <translation>正在寻找可行的最大摆角，若没有则寻找摆臂长……</translation>
    </message>
    <message>
        <source>looking for a roller, else another value, that gives one…</source>
        <translation>正在寻找可行的滚子半径，若没有则寻找其他可改的值……</translation>
    </message>
    <message>
        <source>looking for the least allowance, else a swing, that gives one…</source>
        <translation>正在寻找可行的最小许用压力角，若没有则寻找最大摆角……</translation>
    </message>
    <message>
        <source>looking for an arm that gives one…</source>
        <translation>正在寻找可行的摆臂长……</translation>
    </message>
    <message>
        <source>looking for what leaving the cam to the synthesis gives…</source>
        <translation>正在计算将校核值留空后综合给出的结果……</translation>
    </message>
    <message>
        <source>must be between |a − l| = %1 mm and a + l = %2 mm for the arm to reach the cam</source>
        <translation>须在 |a − l| = %1 mm 与 a + l = %2 mm 之间，摆臂才能接触凸轮</translation>
    </message>
    <message>
        <source>give the base radius and the centre distance together to check a cam</source>
        <translation>校核凸轮须同时给出基圆半径和中心距</translation>
    </message>
    <message>
        <source>the profile's smallest radius r0 − r = %1 mm is %2 mm short of hub + clearance = %3 mm</source>
        <translation>实际廓线最小半径 r0 − r = %1 mm，比轮毂半径 + 间隙 = %3 mm 小 %2 mm</translation>
    </message>
    <message>
        <source>the profile's largest radius %1 mm reaches %2 mm past a − boss − clearance = %3 mm</source>
        <translation>实际廓线最大半径 %1 mm，超出 a − 凸台半径 − 间隙 = %3 mm 达 %2 mm</translation>
    </message>
    <message>
        <source>no cam within the allowances takes a roller of %1 mm or more and clears the hub and the pivot boss, with any arm up to %2 mm</source>
        <translation>摆臂长不超过 %2 mm 时，许用压力角内没有能装下 %1 mm 及以上滚子并避开轮毂和摆动中心凸台的凸轮</translation>
    </message>
    <message>
        <source>is not a design field</source>
        <translation>不是设计参数</translation>
    </message>
    <message>
        <source>is not a load input</source>
        <translation>不是载荷参数</translation>
    </message>
    <message>
        <source>is not a cam field</source>
        <translation>不是凸轮参数</translation>
    </message>
    <message>
        <source>must be text</source>
        <translation>须为文字</translation>
    </message>
    <message>
        <source>must be true or false</source>
        <translation>须为“是”或“否”（布尔值）</translation>
    </message>
    <message>
        <source>must be an object of load inputs</source>
        <translation>须为一组载荷参数</translation>
    </message>
    <message>
        <source>must be an object of cam inputs</source>
        <translation>须为一组凸轮参数</translation>
    </message>
    <message>
        <source>must be one of %1</source>
        <translation>须为下列之一：%1</translation>
    </message>
    <message>
        <source>%1: %2</source>
        <translation>%1：%2</translation>
    </message>
    <message>
        <source>%1 is larger than %2 MB, too large to be a design file</source>
        <translation>%1 大于 %2 MB，不可能是设计文件</translation>
    </message>
    <message>
        <source>%1 does not give %2; these were taken.</source>
        <translation>%1 未给出 %2；已按这些值取用。</translation>
    </message>
    <message>
        <source>%1 is not a shaper design file</source>
        <translation>%1 不是本程序的设计文件</translation>
    </message>
    <message>
        <source>%1 has an unsupported version (%2); this program reads version %3</source>
        <translation>%1 的版本不受支持（%2）；本程序读取第 %3 版</translation>
    </message>
    <message>
        <source>%1 has no version; this program reads version %2</source>
        <translation>%1 没有版本号；本程序读取第 %2 版</translation>
    </message>
    <message>
        <source>%1 holds no design (its 'spec' entry is missing)</source>
        <translation>%1 中没有设计（缺少设计参数）</translation>
    </message>
    <message>
        <source>%1: invalid design (%2)</source>
        <translation>%1：设计无效（%2）</translation>
    </message>
    <message>
        <source>cannot read %1: %2</source>
        <translation>无法读取 %1：%2</translation>
    </message>
    <message>
        <source>%1 is not a regular file</source>
        <translation>%1 不是普通文件</translation>
    </message>
    <message>
        <source>%1 is a folder, not a design file</source>
        <translation>%1 是文件夹，不是设计文件</translation>
    </message>
    <message>
        <source>%1 is not a regular file (a device, pipe or socket)</source>
        <translation>%1 不是普通文件（而是设备、管道或套接字）</translation>
    </message>
    <message>
        <source>%1 is not a design file (not UTF-8 text)</source>
        <translation>%1 不是设计文件（不是 UTF-8 文本）</translation>
    </message>
    <message>
        <source>%1 is not a design file (nested more than %2 levels deep)</source>
        <translation>%1 不是设计文件（嵌套超过 %2 层）</translation>
    </message>
    <message>
        <source>%1 is not a design file (not valid JSON)</source>
        <translation>%1 不是设计文件（不是有效的 JSON）</translation>
    </message>
    <message>
        <source>%1 is not a design file (%2 is not a number a design may hold)</source>
        <translation>%1 不是设计文件（%2 不是设计中可用的数值）</translation>
    </message>
    <message>
        <source>%1 is not a design file (an integer of %2 digits is too large)</source>
        <translation>%1 不是设计文件（%2 位的整数过大）</translation>
    </message>
    <message>
        <source>%1 is not a design file (%2 is too large a number)</source>
        <translation>%1 不是设计文件（数值 %2 过大）</translation>
    </message>
    <message>
        <source>%1 is not a design file (the key %2 appears twice in one object)</source>
        <translation>%1 不是设计文件（同一对象中键 %2 出现了两次）</translation>
    </message>
    <message>
        <source>%1 is not one line of text (it holds a control character or a noncharacter)</source>
        <translation>%1 不是单行文本（含有控制字符或非字符码位）</translation>
    </message>
    <message>
        <source>too fine: %1 samples, limit %2; &apos;shaper library export&apos; with --step %3 writes it at a step a design file holds</source>
        <translation>过细：%1 个采样点，上限 %2；用 &apos;shaper library export&apos; 加 --step %3 可按设计文件能容纳的步长导出</translation>
    </message>
    <message>
        <source>%1: 'spec' must be an object of design fields</source>
        <translation>%1：设计参数须为一组设计字段</translation>
    </message>
    <message>
        <source>no cam within the allowances takes a roller of %1 mm or more and clears the hub and the pivot boss; an arm of %2 mm gives one</source>
        <translation>许用压力角内没有能装下 %1 mm 及以上滚子并避开轮毂和摆动中心凸台的凸轮；摆臂长 %2 mm 时可以</translation>
    </message>
    <message>
        <source>%1: 'rpm' must be a list of crank speeds in r/min</source>
        <translation>%1：曲柄转速须为以 r/min 计的一列数值</translation>
    </message>
    <message>
        <source>%1: crank speed %2 is not a number</source>
        <translation>%1：曲柄转速 %2 不是数值</translation>
    </message>
    <message>
        <source>%1: 'step_deg' must be a number of degrees</source>
        <translation>%1：角度步长须为以度计的数值</translation>
    </message>
    <message>
        <source>the disk is full (no space left on the device)</source>
        <translation>磁盘已满（设备上没有剩余空间）</translation>
    </message>
    <message>
        <source>the disk quota is exhausted</source>
        <translation>磁盘配额已用完</translation>
    </message>
    <message>
        <source>the file system is read-only</source>
        <translation>文件系统为只读</translation>
    </message>
    <message>
        <source>the file does not exist</source>
        <translation>文件不存在</translation>
    </message>
    <message>
        <source>%1 is empty</source>
        <translation>%1 为空</translation>
    </message>
    <message>
        <source>%1 is not text</source>
        <translation>%1 不是文本</translation>
    </message>
    <message>
        <source>%1 is not a whole number</source>
        <translation>%1 不是整数</translation>
    </message>
    <message>
        <source>%1 is not a number</source>
        <translation>%1 不是数值</translation>
    </message>
    <message>
        <source>%1 is not a finite number</source>
        <translation>%1 不是有限数值</translation>
    </message>
    <message>
        <source>there is no design document</source>
        <translation>缺少设计文档</translation>
    </message>
    <message>
        <source>the design document is not UTF-8 text</source>
        <translation>设计文档不是 UTF-8 文本</translation>
    </message>
    <message>
        <source>its design document cannot be opened (%1)</source>
        <translation>其设计文档无法打开（%1）</translation>
    </message>
    <message>
        <source>crank speeds</source>
        <translation>曲柄转速</translation>
    </message>
    <message>
        <source>tags</source>
        <translation>标签</translation>
    </message>
    <message>
        <source>permission denied</source>
        <translation>没有权限</translation>
    </message>
    <message>
        <source>no cam within the allowances clears the pivot boss; the smallest: its profile's largest radius %1 mm reaches %2 mm past a − boss − clearance = %3 mm</source>
        <translation>在许用压力角内没有能避开摆动中心凸台的凸轮；最小的凸轮：实际廓线最大半径 %1 mm，超出 a − 凸台半径 − 间隙 = %3 mm 达 %2 mm</translation>
    </message>
    <message>
        <source>the folder does not exist</source>
        <translation>文件夹不存在</translation>
    </message>
    <message>
        <source>too many levels of symbolic links</source>
        <translation>符号链接层数过多</translation>
    </message>
    <message>
        <source>the name is too long</source>
        <translation>名称过长</translation>
    </message>
    <message>
        <source>a part of the path is not a folder</source>
        <translation>路径中有一部分不是文件夹</translation>
    </message>
    <message>
        <source>it is a folder</source>
        <translation>它是文件夹</translation>
    </message>
    <message>
        <source>an input/output error</source>
        <translation>输入/输出错误</translation>
    </message>
    <message>
        <source>library entry “%1”</source>
        <translation>设计库条目“%1”</translation>
    </message>
</context>
<context>
    <name>model</name>
    <message>
        <source>revert invalid inputs</source>
        <translation>恢复无效输入</translation>
    </message>
    <message>
        <source>switch input mode</source>
        <translation>切换输入方式</translation>
    </message>
    <message>
        <source>edit %1 fields</source>
        <translation>编辑 %1 个字段</translation>
    </message>
</context>
</TS>
